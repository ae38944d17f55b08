# wheeljogpins.tcl: enable wheel jogging (jog-enable 1, jog-scale) for every axis and joint;
# the one argument is the scale (default 1). Joints past num_joints simply end the list.

set scale [expr {[llength $::argv] == 1 ? [lindex $::argv 0] : 1}]
catch {
    foreach letter {x y z a b c u v w} {
        setp axis.$letter.jog-enable 1
        setp axis.$letter.jog-scale $scale
    }
    for {set joint 0} {$joint < 9} {incr joint} {
        setp joint.$joint.jog-enable 1
        setp joint.$joint.jog-scale $scale
    }
}
