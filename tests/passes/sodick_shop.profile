# A shop's Sodick profile for the pass corpus (docs/machines.md): the built-in sodick's reading,
# a workpiece of 20 mm, and the speeds of the shop's three machining conditions (mm/min).
name = sodick_shop
summary = a Sodick shop's conditions, for the time estimate
arc_centre = incremental
integer_unit = mm
semicolon = end-of-block
thickness = 20
code C = condition: machining condition number: selects a row of the condition table
condition_speed C001 = 4
condition_speed C002 = 12
condition_speed c003 = 15
