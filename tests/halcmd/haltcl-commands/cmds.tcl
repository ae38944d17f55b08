# HAL commands as Tcl commands: loadrt, net, setp with expressions, INI lists, show prints.
puts "kins=[lindex $::KINS(KINEMATICS) 0] words=[llength [lindex $::KINS(KINEMATICS) 0]]"
puts "halfiles=[llength $::HAL(HALFILE)] last=[lindex $::HAL(HALFILE) end]"
puts "argv=$::argv argc=$::argc"
loadrt scale names=s1,s2
for {set i 1} {$i <= 2} {incr i} {
    setp s$i.gain [expr {$::APP(GAIN) * $i}]
}
setp s1.offset .25
setp s2.offset 1.0/4
net chain s1.out => s2.in
puts "s1.gain=[getp s1.gain] s2.gain=[getp s2.gain] s1.offset=[getp s1.offset] s2.offset=[getp s2.offset]"
puts "type=[ptype s1.out] sig=[hal stype chain]"
puts "pins=[hal list pin s1.o]"
newsig flag bit
sets flag TRUE
puts "flag=[hal gets flag]"
set shown [show sig chain]
puts "show returned '[string length $shown]' chars"
if {[catch {net chain s2.out} msg]} { puts "caught: $msg" }
source sub.hal
puts "sub: [getp s2.gain]"
net bogus nosuch.pin
