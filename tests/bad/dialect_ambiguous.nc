; 2:1: error: the 4-axis words fit more than one dialect, xyuv-abs or xyuv-rel: U/V on line 2 with nothing that tells whether U V are absolute or relative (mean |U - X|, |V - Y| 1.500 against mean |U|, |V| 2.500 over 2 words) [K0215]
G01 X1. Y1. U2. V3.
M02
