(cnc3's taper calibration cone, written as its own generator writes it [papayaved/cnc3 gcode.cpp,)
(GCode::generate for tapered cutting]: the guides L = 100 mm apart, the lower one H = 30 mm under)
(the work, the work T = 20 mm thick, the U V motors' travel UV_MAX = 15 mm. Its sizing)
([uv_sizing_widget.cpp, calcDia] gives the bottom circle [L - H + T] UV_MAX / L = 13.5 mm and the)
(top [L - H - T] UV_MAX / L = 7.5 mm across; from the faces and M100, Kerf must find the upper guide)
(15 mm from the lower at the circle's axis points: UV_MAX. The entry line runs 5 mm along -Y.)
M100 P100. Q30.
M101 P20.
G92 X0 Y0 U0 V0
G1 X0 Y-5. U0 V-8.
G2 X6.75 Y-11.75 I0 J-6.75 U3.75 V-11.75 I0 J-3.75
G2 X0 Y-18.5 I-6.75 J0 U0 V-15.5 I-3.75 J0
G2 X-6.75 Y-11.75 I0 J6.75 U-3.75 V-11.75 I0 J3.75
G2 X0 Y-5. I6.75 J0 U0 V-8. I3.75 J0
G1 X0 Y0 U0 V0
M2
