# second HAL file (haltcl): arguments, INI arrays, expressions
loadrt sum2 names=total
setp total.gain0 [expr {[lindex $::TRAJ(MAX_LINEAR_VELOCITY) 0] * 2}]
puts "second.tcl: argv=$::argv joints=$::KINS(JOINTS)"
