; 2:10: error: J = 40000 µm runs past a full circle: a full turn of this arc (R 9.900 mm) counts 39600 µm [K0308]
B9900 B0 B40000 GY NR1
DD
