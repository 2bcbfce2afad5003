L unterprogramm_ה.nc
LL Rückzug
N10 G0 X0 (Kommentar הצü)
M30
