; 2:1: error: unknown word letter 'B' [K0107]
B9900 B0 B9900 GX L3
DD
