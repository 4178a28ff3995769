(I J written as start minus centre, as some Agie/Charmilles/Mitsubishi posts do)
G90 G92 X20. Y0
G01 X10. Y0
G03 X-10. Y0 I10. J0
G03 X10. Y0 I-10. J0
G01 X20. Y0
M02
