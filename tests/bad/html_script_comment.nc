; 3:13: error: 'B' turns a rotary axis while the wire moves: Kerf does not model it, so this move cannot be checked [K0107]
G92 X0 Y0
G01 X10. Y0 B5 (</script><script>document.title="pwned"</script>)
G01 X10. Y10.
X0 Y0
M02
