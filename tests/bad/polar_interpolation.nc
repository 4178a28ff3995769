; 5:12: error: C-358.834 turns the table 358.834 degrees from C0.000, more than the shortest way (1.166 degrees): the part turns under the tool [K0237]
(seed 002, Fig. 7: a C written the long way round damaged the part)
G28 C0.
G1 X28. C0. F100
G1 X28.006 C-358.834
M30
