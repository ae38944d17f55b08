# basic_sim.tcl: a simulated machine for any [TRAJ]COORDINATES and [KINS]JOINTS (haltcl HALFILE).
# Options (HALFILE arguments): -no_make_ddts -no_simulated_home -no_use_hal_manualtoolchange
# -no_sim_spindle. The HAL commands of the result are saved as <ini name>_cmds.hal.

source [file join $::env(HALLIB_DIR) sim_lib.tcl]

set ::SIM_LIB(options) [string tolower $::argv]

# True unless the HALFILE arguments contain -no_<what>.
proc wanted {what} {
    return [expr {"-no_$what" ni $::SIM_LIB(options)}]
}

if {[catch {check_ini_items} msg]} {
    puts "\nbasic_sim.tcl ERROR: $msg\n"
    exit 1
}

set axes [get_traj_coordinates]
set number_of_joints [lindex $::KINS(JOINTS) 0]
set base_period [expr {[info exists ::EMCMOT(BASE_PERIOD)] ? [lindex $::EMCMOT(BASE_PERIOD) 0] : 0}]
set emcmot [expr {[info exists ::EMCMOT(EMCMOT)] ? [lindex $::EMCMOT(EMCMOT) 0] : "motmod"}]

core_sim $axes $number_of_joints [lindex $::EMCMOT(SERVO_PERIOD) 0] $base_period $emcmot
set used {}
foreach {what call} {make_ddts {make_ddts $number_of_joints}
                     simulated_home {simulated_home $number_of_joints}
                     use_hal_manualtoolchange use_hal_manualtoolchange
                     sim_spindle sim_spindle} {
    if {[wanted $what]} {
        eval $call
        lappend used $what
    }
}

set inifile [expr {[info exists ::env(INI_FILE_NAME)] ? $::env(INI_FILE_NAME) : "basic_sim.ini"}]
save_hal_cmds ./[file rootname [file tail $inifile]]_cmds.hal $used
