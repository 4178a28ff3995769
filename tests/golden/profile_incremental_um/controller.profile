# A made-up controller: µm integers, incremental moves, N-numbered lines.
name = test-controller
unit = um
coordinates = incremental
separator = comma
line_numbers = true
line_number_prefix = "P"
line_number_start = 0
header = "START\nPROGRAM 1"
footer = "END"
