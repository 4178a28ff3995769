; 5:11: error: arc radius 2.000 is shorter than half the chord 7.071 mm [K0302]
G92 X0 Y0
G01 X10. Y0
X10. Y10.
G02 X0 Y0 R-2. (<img src=x onerror="document.title=1"><b id=pwned>bold</b>)
M02
