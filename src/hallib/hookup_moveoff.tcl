# hookup_moveoff.tcl: insert the moveoff component (named mv) between motion and the joints, so
# offsets can be applied while a program is paused. Must follow the HAL files that connect
# joint.N.motor-pos-cmd and joint.N.motor-pos-fb. Limits per joint from [MOVEOFF_n], else
# [JOINT_n]; [MOVEOFF] EPSILON, WAYPOINT_SAMPLE_SECS, WAYPOINT_THRESHOLD, BACKTRACK_ENABLE.

source [file join $::env(HALLIB_DIR) hal_procs_lib.tcl]

# Joints with a [JOINT_n]TYPE entry (n = 0..8).
proc hu_joints {} {
    set joints {}
    for {set n 0} {$n < 9} {incr n} {
        if {[info exists ::JOINT_${n}(TYPE)]} { lappend joints $n }
    }
    return $joints
}

# Last value of [section]key, or "" when absent.
proc hu_ini {section key} {
    upvar #0 $section arr
    if {[info exists arr($key)]} { return [lindex $arr($key) end] }
    return ""
}

# Run a HAL command, remembering it for the failure report.
proc hu_do {args} {
    set ::HU(cmd) $args
    return [hal {*}$args]
}

# Record how a joint pin is connected (signal, writer, readers) and unlink it.
proc hu_take {joint pin} {
    set name joint.$joint.$pin
    if {[is_connected $name sig] eq "not_connected"} {
        return -code error "$name not connected as expected"
    }
    get_netlist readers writer ios $sig
    set ::HU($joint,$pin,sig) $sig
    set ::HU($joint,$pin,writer) $writer
    set ::HU($joint,$pin,readers) $readers
    hu_do unlinkp $name
}

# Rewire one joint through mv.
proc hu_joint {a} {
    hu_take $a motor-pos-cmd
    hu_take $a motor-pos-fb
    set short [expr {$::HU($a,motor-pos-cmd,sig) eq $::HU($a,motor-pos-fb,sig)}]
    set fb_pin joint.$a.motor-pos-fb
    set cmd_readers [lsearch -all -inline -not -exact $::HU($a,motor-pos-cmd,readers) $fb_pin]
    foreach pin $cmd_readers { hu_do unlinkp $pin }
    hu_do delsig $::HU($a,motor-pos-cmd,sig)
    hu_do net hu:pos-$a joint.$a.motor-pos-cmd mv.pos-$a
    hu_do net hu:minus-$a mv.fb-minusoffset-$a $fb_pin
    if {$short} {
        hu_do net hu:shortcircuit-$a mv.pos-plusoffset-$a mv.fb-$a {*}$cmd_readers
        return
    }
    if {[llength $cmd_readers]} {
        hu_do net hu:plus-$a mv.pos-plusoffset-$a {*}$cmd_readers
    } else {
        hu_do net hu:plus-$a mv.pos-plusoffset-$a
    }
    set fb_readers [lsearch -all -inline -not -exact $::HU($a,motor-pos-fb,readers) $fb_pin]
    foreach pin $fb_readers { hu_do unlinkp $pin }
    set writer $::HU($a,motor-pos-fb,writer)
    foreach pin $writer { hu_do unlinkp $pin }
    hu_do delsig $::HU($a,motor-pos-fb,sig)
    hu_do net hu:fb-$a {*}$writer mv.fb-$a {*}$fb_readers
}

# Offset limits of one joint from [MOVEOFF_a], else [JOINT_a].
proc hu_limits {a} {
    foreach {pin key} {offset-vel MAX_VELOCITY offset-accel MAX_ACCELERATION
                       offset-max MAX_LIMIT offset-min MIN_LIMIT} {
        set value [hu_ini MOVEOFF_$a $key]
        if {$value eq ""} {
            set value [hu_ini JOINT_$a $key]
            if {$value eq ""} continue
            puts "hookup_moveoff.tcl:use \[JOINT_$a\]$key=$value"
        }
        hu_do setp mv.$pin-$a $value
    }
}

# Load mv around motion-controller and rewire every joint.
proc hu_hookup {} {
    set thread [thread_info ti]
    if {$thread eq ""} { return -code error "motion-controller is not on any thread" }
    set joints [hu_joints]
    hu_do loadrt moveoff personality=[expr {[lindex $joints end] + 1}] names=mv
    hu_do addf mv.write-outputs $thread [expr {$ti(motion-controller,index) + 1}]
    set handler_index [expr {[info exists ti(motion-command-handler,index)] ?
                             $ti(motion-command-handler,index) : 1}]
    hu_do addf mv.read-inputs $thread [expr {$handler_index == 1 ? 1 : $handler_index - 1}]
    foreach a $joints {
        hu_joint $a
        hu_limits $a
    }
    foreach {pin key} {epsilon EPSILON waypoint-sample-secs WAYPOINT_SAMPLE_SECS
                       waypoint-threshold WAYPOINT_THRESHOLD backtrack-enable BACKTRACK_ENABLE} {
        set value [hu_ini MOVEOFF $key]
        if {$value ne ""} { hu_do setp mv.$pin $value }
    }
}

if {[namespace exists ::tp] && [::tp::passnumber] == 0} {
    puts "hookup_moveoff.tcl: twopass active, pass 0 skipped"
    return
}
if {[namespace exists ::tp]} {
    puts "hookup_moveoff.tcl: twopass active, pass 1 active"
}
set ::HU(cmd) ""
if {[catch {hu_hookup} msg]} {
    puts "hookup_moveoff.tcl: argv=$::argv"
    parray ::HU
    puts "failing cmd=$::HU(cmd)"
    puts "msg=<$msg>"
    return -code error $msg
}
