; 4:21: error: ',R1.': Kerf rounds corners in 2-axis and taper-angle programs; a xyuv-abs program gives each plane's contour itself [K0240]
M101 P10.
G90 G92 X0 Y0 U0 V0
G01 X10. Y0 U11. V0 ,R1.
X10. Y10. U11. V11.
M02
