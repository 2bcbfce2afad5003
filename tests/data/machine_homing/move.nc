; X requires homing (P-AXIS-00277): with nck run --unhomed this block is refused (930740)
G90 G0 X20 Y10
G1 X40 F1000
M30
