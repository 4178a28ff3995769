; 2:1: error: macro B statement: variables, loops and jumps (#, WHILE, IF, GOTO) are evaluated by the control, and Kerf does not run them [K0113]
#1=5
M02
