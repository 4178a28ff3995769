; 5:11: error: arc radius 2.000 is shorter than half the chord 7.071 mm [K0302]
G92 X0 Y0
G01 X10. Y0 (<!-- ]]> &amp; â€¨ </style><style>*{display:none}</style></script>)
X10. Y10. (ÿþ not UTF-8)
G02 X0 Y0 R-2.
M02
