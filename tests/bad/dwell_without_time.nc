; 2:1: error: G04 needs a time: P (milliseconds) or X (seconds) [K0208]
G04
M02
