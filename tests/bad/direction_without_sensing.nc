; 2:5: error: 'Y+' gives a direction, not a coordinate: that belongs to an edge-sensing code [K0234]
G01 Y+
M02
