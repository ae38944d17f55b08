# Tcl HAL file: hal command results, INI arrays, loops and errors
hal loadrt and2 count=2
foreach i {0 1} {
    hal net sig$i and2.$i.out
}
hal setp and2.0.in0 1
puts [hal getp and2.0.in0]
puts "scale=$::AXIS_0(SCALE) names=[llength $::AXIS_0(NAME)]"
puts [hal list sig]
hal newsig flag bit
hal sets flag $::AXIS_0(FLAG)
puts [hal gets flag]
if {[catch {hal setp and2.0.out 1} err]} { puts "caught: $err" }
puts [hal show pin and2.1.out]
