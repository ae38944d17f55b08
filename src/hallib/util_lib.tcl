# util_lib.tcl: small helpers for HAL Tcl files: context and INI dumps (quiet in twopass
# pass 0) and the joint number of an axis letter for trivkins.

set ::util_lib_quiet [expr {[namespace exists ::tp] && [::tp::passnumber] == 0}]

# Print how the script was started (argv0, argv, each argument, INI_FILE_NAME).
proc show_context {} {
    if {$::util_lib_quiet} return
    puts "argv0=$::argv0"
    puts "argv=$::argv"
    set i 0
    foreach arg $::argv {
        puts "  arg$i=$arg"
        incr i
    }
    if {[info exists ::env(INI_FILE_NAME)]} { puts "INI_FILE_NAME=$::env(INI_FILE_NAME)" }
}

# Print every INI array (all global arrays but Tcl's own and the twopass one).
proc show_ini {} {
    if {$::util_lib_quiet} return
    foreach name [lsort [info globals]] {
        if {$name in {TP auto_index tcl_platform env}} continue
        if {[array exists ::$name]} { parray ::$name }
    }
}

# Print the environment.
proc show_env {} {
    parray ::env
}

# The joint number of axis letter L ($KINS_KINEMATICS must be trivkins; $TRAJ_COORDINATES
# gives the letters, separated by blanks or not).
proc joint_number_for_axis {letter} {
    set kins [lindex $::env(KINS_KINEMATICS) 0]
    if {$kins ne "trivkins"} {
        return -code error "joint_number_for_axis: $letter unavailable for kinematics: $kins"
    }
    set coords [string toupper $::env(TRAJ_COORDINATES)]
    if {[llength $coords] == 1} { set coords [split $coords ""] }
    set index [lsearch -exact $coords [string toupper $letter]]
    if {$index < 0} {
        return -code error "joint_number_for_axis $letter not in $coords"
    }
    return $index
}
