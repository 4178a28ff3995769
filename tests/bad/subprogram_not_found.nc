; 2:5: error: no subprogram O77 or N77 in this file [K0502]
M98 P77
M02
