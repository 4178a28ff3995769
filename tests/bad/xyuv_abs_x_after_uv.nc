; 3:20: error: 'X' on the upper side: xyuv-abs gives the upper contour as U V (this program is read as xyuv-abs) [K0206]
M101 P20
G1 X10. Y0 U10. V0 X11.
M2
