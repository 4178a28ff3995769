; Three punches, each cut once counter-clockwise with G42 H001 (0.1 mm, outside) from a start
; hole to its left, each under its own machining condition (C001, C002, C003; Sodick: ';' ends
; blocks). The first punch is a 16-sided polygon: the wire offset inserts an arc at each of its 16
; convex corners, so the moves after it move 16 places down the list, past where C003 was
; selected. Each pass must keep its own condition, and its time that condition's speed
; [sodick_shop.profile: C001 4, C002 12, C003 15 mm/min] - issue 55: the second punch was said to
; be under C003.
; By hand: the second and third punches are 10 x 10 squares cut 0.1 mm outside: four sides of
; 10 mm and four quarter circles of radius 0.1 mm, 40.628 mm, and 4.9 mm each way from the start hole
; to the wire path: 50.428 mm, at 12 and 15 mm/min 4.202 and 3.362 min.
; Read with tests/passes/sodick_shop.profile by the cli test tables_follow_inserted_moves.
H001 = +000000.1000;
G90 G92 X-5. Y0;
C001;
G42 H001 G01 X0 Y0;
X0.7612 Y-3.8268;
X2.9289 Y-7.0711;
X6.1732 Y-9.2388;
X10.0000 Y-10.0000;
X13.8268 Y-9.2388;
X17.0711 Y-7.0711;
X19.2388 Y-3.8268;
X20.0000 Y0;
X19.2388 Y3.8268;
X17.0711 Y7.0711;
X13.8268 Y9.2388;
X10.0000 Y10.0000;
X6.1732 Y9.2388;
X2.9289 Y7.0711;
X0.7612 Y3.8268;
X0.0000 Y0.0000;
G40 G01 X-5. Y0;
M00;
G00 X25. Y5.;
C002;
G42 H001 G01 X30. Y5.;
Y0;
X40.;
Y10.;
X30.;
Y5.;
G40 G01 X25. Y5.;
M00;
G00 X45. Y5.;
C003;
G42 H001 G01 X50. Y5.;
Y0;
X60.;
Y10.;
X50.;
Y5.;
G40 G01 X45. Y5.;
M02;
