(A frustum punch in absolute U V [xyuv-abs]: the lower face 40 x 20 mm, the upper 36 x 16 over)
(its middle, cut counter-clockwise with G42 outside both. Each plane's contour is offset by the)
(same 0.15 mm, the corner arcs paired move by move. Read with --offset 0.15 --thickness 10.)
G90 G92 X-5. Y10. U-5. V10.
G42 G01 X0 Y10. U2. V10.
X0 Y0 U2. V2.
X40. Y0 U38. V2.
X40. Y20. U38. V18.
X0 Y20. U2. V18.
X0 Y10. U2. V10.
G40 G01 X-5. Y10. U-5. V10.
M02
