# sim_lib.tcl: procedures that build a simulated machine of any joint count (used by
# basic_sim.tcl under haltcl). Each joint is a pid (pure feed-forward) into a sample-and-hold
# mux2, so feedback follows the command while motion is enabled and holds when it is not.

# Joint number of each axis letter for trivkins: letters in order (a repeated letter keeps
# its last joint), stored in ::SIM_LIB(jointidx,<letter>).
proc indices_for_trivkins {axes} {
    if {$axes eq ""} { set axes {x y z a b c u v w} }
    set i 0
    foreach letter [string tolower $axes] {
        set ::SIM_LIB(jointidx,$letter) $i
        incr i
    }
}

# The [TRAJ]COORDINATES letters, lower case, one list element each ("X Y Z" and "XYZ" alike).
proc get_traj_coordinates {} {
    set text [lindex $::TRAJ(COORDINATES) 0]
    set text [string map {" " "" "\t" ""} $text]
    return [split [string tolower $text] ""]
}

# Refuse INI files this library cannot build a machine for; warn about joint count mismatches.
proc check_ini_items {} {
    foreach {section key} {KINS KINEMATICS KINS JOINTS TRAJ COORDINATES} {
        if {![info exists ::${section}($key)]} {
            return -code error "Missing inifile item: \[$section\]$key"
        }
    }
    if {[info exists ::DISPLAY(LATHE)]} {
        foreach kins $::KINS(KINEMATICS) {
            if {[string trim $kins] eq "trivkins"} {
                return -code error "Lathe configuration with trivkins must specify\
                    coordinates= in \[KINS\]KINEMATICS (for example: trivkins coordinates=XZ)"
            }
        }
    }
    set kins [lindex $::KINS(KINEMATICS) end]
    if {[lindex $kins 0] ne "trivkins"} return
    set letters ""
    foreach arg [lrange $kins 1 end] {
        if {[string match coordinates=* $arg]} { set letters [string range $arg 12 end] }
    }
    if {$letters eq ""} return
    set extra 0
    if {[info exists ::EMCMOT(EMCMOT)]} {
        foreach arg [lindex $::EMCMOT(EMCMOT) 0] {
            if {[string match num_extrajoints=* $arg]} { set extra [string range $arg 16 end] }
        }
    }
    set joints [lindex $::KINS(JOINTS) 0]
    if {[string length $letters] + $extra != $joints} {
        puts stderr "check_ini_items: WARNING:\
            \n  trivkins coordinates=$letters gives [string length $letters] joints\
            \n  plus num_extrajoints=$extra\
            \n  but \[KINS\]JOINTS=$joints"
    }
}

# Load the kinematics module ([KINS]KINEMATICS, last value) and learn its joint numbering.
proc setup_kins {axes} {
    if {![info exists ::KINS(KINEMATICS)]} {
        puts stderr "setup_kins: no \[KINS\]KINEMATICS, using trivkins"
        set kins trivkins
    } else {
        set kins [lindex $::KINS(KINEMATICS) end]
    }
    set cmd "loadrt $kins"
    puts stderr "setup_kins: cmd=$cmd"
    if {[catch {eval $cmd} msg]} {
        puts stderr "setup_kins: msg=$msg"
    }
    if {[lindex $kins 0] eq "trivkins"} {
        indices_for_trivkins $axes
    } else {
        puts stderr "setup_kins: unknown \[KINS\]KINEMATICS=<$kins>"
    }
}

# setp that is also recorded for save_hal_cmds (pin values are not part of `save all`).
proc do_setp {name value} {
    setp $name $value
    lappend ::SIM_LIB(setp_list) [list $name $value]
}

# A comma-separated names= list: <prefix><n><suffix> for joints 0..count-1.
proc joint_names {count suffix} {
    set names {}
    for {set n 0} {$n < $count} {incr n} { lappend names J${n}$suffix }
    return [join $names ,]
}

# Kinematics, motion, and per joint a pid (feed-forward only) into a sample-and-hold mux2.
proc core_sim {axes number_of_joints servo_period {base_period 0} {emcmot motmod}} {
    setup_kins $axes
    set timing "base_period_nsec=$base_period servo_period_nsec=$servo_period\
                num_joints=$number_of_joints"
    set module [lindex $emcmot 0]
    if {[string trim $emcmot] eq "motmod"} {
        set cmd "loadrt motmod $timing"
    } else {
        set cmd "loadrt $module [lrange $emcmot 1 end] $timing"
    }
    if {[catch {eval $cmd} msg]} {
        puts stderr "\ncore_sim: loadrt $module FAIL\n  cmd=$cmd\n  msg=$msg\n"
        exit 1
    }
    addf motion-command-handler servo-thread
    addf motion-controller servo-thread
    loadrt pid names=[joint_names $number_of_joints _pid]
    loadrt mux2 names=[joint_names $number_of_joints _mux]
    for {set n 0} {$n < $number_of_joints} {incr n} {
        addf J${n}_pid.do-pid-calcs servo-thread
        do_setp J${n}_pid.FF0 1.0
        foreach gain {Pgain Dgain Igain FF1 FF2} { do_setp J${n}_pid.$gain 0 }
    }
    for {set n 0} {$n < $number_of_joints} {incr n} { addf J${n}_mux servo-thread }
    net estop:loop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in
    net tool:prep-loop iocontrol.0.tool-prepare => iocontrol.0.tool-prepared
    net tool:change-loop iocontrol.0.tool-change => iocontrol.0.tool-changed
    net sample:enable motion.motion-enabled
    for {set n 0} {$n < $number_of_joints} {incr n} {
        net sample:enable => J${n}_mux.sel
        net J${n}:enable joint.$n.amp-enable-out => J${n}_pid.enable
        net J${n}:pos-cmd joint.$n.motor-pos-cmd => J${n}_pid.command
        net J${n}:on-pos J${n}_pid.output => J${n}_mux.in1
        net J${n}:pos-fb J${n}_mux.out => J${n}_mux.in0 joint.$n.motor-pos-fb
    }
}

# Velocity and acceleration of every joint; XY and XYZ path speed when x, y, z are joints.
proc make_ddts {number_of_joints} {
    set names {}
    for {set n 0} {$n < $number_of_joints} {incr n} { lappend names J${n}_vel J${n}_accel }
    loadrt ddt names=[join $names ,]
    for {set n 0} {$n < $number_of_joints} {incr n} {
        addf J${n}_vel servo-thread
        addf J${n}_accel servo-thread
        net J${n}:pos-fb => J${n}_vel.in
        net J${n}:vel J${n}_vel.out => J${n}_accel.in
        net J${n}:acc <= J${n}_accel.out
    }
    foreach letter {x y z} {
        if {![info exists ::SIM_LIB(jointidx,$letter)]} return
    }
    set jx $::SIM_LIB(jointidx,x)
    set jy $::SIM_LIB(jointidx,y)
    set jz $::SIM_LIB(jointidx,z)
    loadrt hypot names=hyp_xy,hyp_xyz
    addf hyp_xy servo-thread
    addf hyp_xyz servo-thread
    net J${jx}:vel => hyp_xy.in0 hyp_xyz.in0
    net J${jy}:vel => hyp_xy.in1 hyp_xyz.in1
    net J${jz}:vel => hyp_xyz.in2
    net xy:vel <= hyp_xy.out
    net xyz:vel <= hyp_xyz.out
}

# Ask the operator for tool changes (hal_manualtoolchange) instead of the loop-back.
proc use_hal_manualtoolchange {} {
    loadusr -W hal_manualtoolchange
    unlinkp iocontrol.0.tool-change
    unlinkp iocontrol.0.tool-changed
    delsig tool:change-loop
    net tool:change iocontrol.0.tool-change => hal_manualtoolchange.change
    net tool:changed hal_manualtoolchange.changed => iocontrol.0.tool-changed
    net tool:prep-number iocontrol.0.tool-prep-number => hal_manualtoolchange.number
}

# A home switch per joint at the joint's fed-back position (sim_home_switch).
proc simulated_home {number_of_joints} {
    loadrt sim_home_switch names=[joint_names $number_of_joints _switch]
    set inch [expr {[info exists ::TRAJ(LINEAR_UNITS)] &&
                    [lindex $::TRAJ(LINEAR_UNITS) 0] in {in inch imperial}}]
    for {set n 0} {$n < $number_of_joints} {incr n} {
        addf J${n}_switch servo-thread
        net J${n}:pos-fb => J${n}_switch.cur-pos
        net J${n}:homesw J${n}_switch.home-sw => joint.$n.home-sw-in
        upvar #0 JOINT_$n joint
        if {[info exists joint(TYPE)] && [lindex $joint(TYPE) 0] ne "ANGULAR"} {
            if {$inch} {
                do_setp J${n}_switch.hysteresis 0.05
                do_setp J${n}_switch.home-pos 0.10
            }
            if {[info exists joint(HOME_SEARCH_VEL)] &&
                [string is double -strict [lindex $joint(HOME_SEARCH_VEL) 0]] &&
                [lindex $joint(HOME_SEARCH_VEL) 0] < 0} {
                do_setp J${n}_switch.home-pos [expr {-1 * [getp J${n}_switch.home-pos]}]
            }
        }
        if {[info exists joint(HOME_USE_INDEX)] &&
            [string is true -strict [lindex $joint(HOME_USE_INDEX) 0]]} {
            net J${n}:index-enable joint.$n.index-enable <=> J${n}_switch.index-enable
        }
    }
}

# Simulated spindle with mass, at-speed and instant orientation (as sim_spindle_encoder.hal).
proc sim_spindle {} {
    loadrt sim_spindle names=sim_spindle
    do_setp sim_spindle.scale 0.01666667
    loadrt limit2 names=limit_speed
    loadrt lowpass names=spindle_mass
    loadrt near names=near_speed
    loadrt scale names=rpm_rps
    net spindle-index-enable spindle.0.index-enable <=> sim_spindle.index-enable
    net spindle-pos sim_spindle.position-fb => spindle.0.revs
    net spindle-speed-cmd spindle.0.speed-out => limit_speed.in near_speed.in1
    net spindle-speed-limited limit_speed.out => sim_spindle.velocity-cmd spindle_mass.in
    net spindle-rpm-filtered spindle_mass.out => near_speed.in2 rpm_rps.in
    net spindle-rps-filtered rpm_rps.out => spindle.0.speed-in
    net spindle-at-speed near_speed.out => spindle.0.at-speed
    net spindle-orient spindle.0.orient => spindle.0.is-oriented
    do_setp rpm_rps.gain .0167
    do_setp limit_speed.maxv 5000.0
    do_setp spindle_mass.gain .07
    do_setp near_speed.scale 1.1
    do_setp near_speed.difference 10
    foreach funct {limit_speed spindle_mass rpm_rps near_speed sim_spindle} {
        addf $funct servo-thread
    }
}

# One `hal save` line as written by save_hal_cmds: aligned setp, preloaded modules commented.
proc save_line {line} {
    if {[regexp {^setp\s+(\S+)\s+(.*)$} $line -> name value]} {
        return [format "%-3s %-30s %s" setp $name [string trim $value]]
    }
    if {[regexp {^loadrt\s+(tpmod|homemod)\M} $line]} {
        return "#preloaded module: $line"
    }
    return $line
}

# Write the HAL commands of the machine just built to file, so it can replace basic_sim.tcl.
proc save_hal_cmds {savefilename {options ""}} {
    set tmp /tmp/save_hal_cmds_tmp[pid]
    set halfiles [expr {[info exists ::HAL(HALFILE)] ? $::HAL(HALFILE) : {}}]
    set what [expr {[llength $halfiles] > 1 ? "allu" : "all"}]
    set f [open $tmp w]
    puts $f "# [clock format [clock seconds]]"
    puts $f "# This file:   $savefilename"
    puts $f "# Created by:  [info script]"
    puts $f "# With options: $::argv"
    puts $f "# From INI file: [expr {[info exists ::env(INI_FILE_NAME)] ? $::env(INI_FILE_NAME) : {}}]"
    puts $f "# HALFILEs:"
    foreach h $halfiles { puts $f "#   $h" }
    puts $f "#"
    puts $f "# To use this file instead of LIB:basic_sim.tcl, replace that \[HAL\]HALFILE"
    puts $f "# entry with this file's name."
    puts $f "# Note: tpmod and homemod are loaded by the launcher (commented out below)."
    puts $f "# Note: pin values set with setp are listed at the end."
    if {[string first use_hal_manualtoolchange $options] >= 0} {
        puts $f "\nloadusr -W hal_manualtoolchange"
    }
    set replaced 0
    foreach line [split [hal save $what] "\n"] {
        if {!$replaced && [string first "unconnected pin values" $line] >= 0} {
            puts $f "# unconnected pin values (as they were when saved):"
            puts $f "# (some of them are set again by the setp lines at the end)"
            set replaced 1
            continue
        }
        puts $f [save_line $line]
    }
    if {$what eq "all" && [info exists ::SIM_LIB(setp_list)]} {
        puts $f "# setp commands of basic_sim.tcl for unconnected input pins"
        foreach pair $::SIM_LIB(setp_list) {
            puts $f [format "%-3s %-30s %s" setp [lindex $pair 0] [lindex $pair 1]]
        }
    }
    close $f
    file rename -force $tmp $savefilename
}
