; Y needs no homing and moves unhomed; G74 homes X and Z, then they may move
G90 G0 Y10
G74 X1 Z2
G0 X20 Z5
G1 X40 F1000
M30
