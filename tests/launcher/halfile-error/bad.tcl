# a Tcl HAL file whose line 3 fails
loadrt ddt names=t1
setp t1.nosuch 1
