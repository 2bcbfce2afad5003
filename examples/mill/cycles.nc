; Mill example: cycle calls. Deep-hole drilling on a hole pattern with a
; modal call in G17, a circular pocket with helical infeed, and one hole
; drilled sideways in G18 (the same cycle: @Z is then the Y axis). The
; cycles are in cycles/, found through startup.lis cycle_path[0]. Runs to M30.
%cycles
N10 G17 G90 G71
N20 S1000 M3
N30 G0 X20 Y20 Z10
; modal call: drills here, then after every motion block
N40 L CYCLE [NAME=drill_deep.ecy MODAL_MOVE \
    @P1=2 @P2=-20 @P3=6 @P4=0.5 @P5=2 @P6=300 @P7=1 ]
N50 G0 X40                    ; second hole
N60 G0 Y40                    ; third hole
N70 #DISABLE MODAL CYCLE
N80 G0 X80 Y30                ; no hole: the modal call is off
N90 L CYCLE [NAME=pocket_circ.ecy \
    @P1=2 @P2=-10 @P3=10 @P4=3 @P5=4 @P6=600 ]
; one hole from the side in G18: the tool axis is Y
N100 G0 Z10
N110 G0 Y60
N120 G0 X60 Z-5
N130 G18
N140 L CYCLE [NAME=drill_deep.ecy @P1=55 @P2=40 @P3=6 @P4=0.5 @P5=3 @P6=300 @P7=1]
N150 G17 G0 Y60
N160 M5
N170 M30
