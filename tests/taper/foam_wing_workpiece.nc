(A hot-wire foam panel in LinuxCNC's XYUV: the carriages X Y at z 0 and U V at z 600, the root)
(100 x 20 mm with a round nose, the tip 60 x 12 over it. The foam block stands between z 100 and)
(400: read with --workpiece 100,400, the part is the wire's cut between those faces. The nose is an)
(XY arc while U V move straight, as LinuxCNC moves them: its sections are no arcs.)
(AXIS,XY_Z_POS,0)
(AXIS,UV_Z_POS,600)
G21 G90
G0 X-10. Y0 U10. V4.
G1 X0 Y0 U20. V4. F300
G1 X100. Y0 U80. V4.
G3 X100. Y20. I0 J10. U80. V16.
G1 X0 Y20. U20. V16.
G1 X0 Y0 U20. V4.
G1 X-10. Y0 U10. V4.
M2
