# b.tcl: the second lowpass, a setp with an expression, and which pass is running
loadrt lowpass names=lp2
puts "b.tcl pass [::tp::passnumber] argv=$::argv"
setp lp2.gain [expr {[lindex $::argv 0] / 10.0}]
addf lp2 servo-thread
