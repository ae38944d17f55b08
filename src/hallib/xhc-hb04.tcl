# xhc-hb04.tcl: connect an XHC-HB04 wireless MPG pendant (user component xhc-hb04 plus
# xhc_hb04_util) to jogging, overrides, halui and the DRO. Configured by [XHC_HB04_CONFIG]
# (layout, coords, coefs, scales, mpg_accels, threadname, sequence, jogmode, require_pendant,
# inch_or_mm; lower-case keys) and [XHC_HB04_BUTTONS] (<button> = <pin>). Needs [HAL]HALUI.

source [file join $::env(HALLIB_DIR) hal_procs_lib.tcl]
source [file join $::env(HALLIB_DIR) util_lib.tcl]

set ::XHC(prog) xhc-hb04.tcl
set ::XHC(failures) {}
set ::XHC(pass0) [expr {[namespace exists ::tp] && [::tp::passnumber] == 0}]

# Tell the operator: stderr, and a Tk message box when a display is available.
proc xhc_popup {msg} {
    puts stderr "$::XHC(prog): $msg"
    catch {
        package require Tk
        wm withdraw .
        tk_messageBox -title $::XHC(prog) -type ok -message $msg
        destroy .
    }
}

# Fatal configuration error.
proc xhc_fail {msg} {
    xhc_popup $msg
    exit 1
}

# Lower-case key value of a section (braces trimmed); an upper-case duplicate with another
# value is reported and dropped.
proc xhc_value {section key default} {
    upvar #0 $section arr
    set upper [string toupper $key]
    if {[info exists arr($upper)] && $upper ne $key} {
        if {[info exists arr($key)] && $arr($key) ne $arr($upper)} {
            puts stderr "$::XHC(prog): duplicated item: \[$section\]$upper=$arr($upper)"
            puts stderr "$::XHC(prog): superseded with: \[$section\]$key=$arr($key)"
        }
        unset arr($upper)
    }
    if {![info exists arr($key)]} { return $default }
    return [string trim [lindex $arr($key) end] "{}"]
}

# Make a net; failures are collected for one message at the end.
proc xhc_net {signame args} {
    if {[catch {net $signame {*}$args} msg]} { lappend ::XHC(failures) "$signame: $msg" }
}

# Net from an OUT pin, reusing the signal the pin already drives.
proc xhc_net_out {outpin signame args} {
    if {[is_connected $outpin existing] eq "is_output"} {
        puts "$::XHC(prog): Using existing outpin signame: $existing"
        set signame $existing
        set outpin ""
    }
    if {$outpin eq ""} {
        xhc_net $signame {*}$args
    } else {
        xhc_net $signame $outpin {*}$args
    }
}

# setp that records a failure instead of stopping.
proc xhc_setp {pin value} {
    if {[catch {setp $pin $value} msg]} { lappend ::XHC(failures) "setp $pin: $msg" }
}

# The standard start/pause button: pendant_util decides run, pause or resume.
proc xhc_std_start_pause {} {
    xhc_net pendant:start-or-pause xhc-hb04.button-start-pause pendant_util.start-or-pause
    xhc_net_out halui.program.is-idle pendant:is-idle pendant_util.is-idle
    xhc_net_out halui.program.is-paused pendant:is-paused pendant_util.is-paused
    xhc_net_out halui.program.is-running pendant:is-running pendant_util.is-running
    xhc_net pendant:program-resume pendant_util.resume halui.program.resume
    xhc_net pendant:program-pause pendant_util.pause halui.program.pause
    xhc_net pendant:program-run pendant_util.run halui.program.run halui.mode.auto
}

# [XHC_HB04_BUTTONS]: one net per button, sorted by name.
proc xhc_buttons {} {
    foreach name [lsort [array names ::XHC_HB04_BUTTONS]] {
        set pin [string trim [lindex $::XHC_HB04_BUTTONS($name) end] "{}"]
        if {$pin eq ""} continue
        if {$name eq "start-pause" && $pin eq "std_start_pause"} {
            xhc_std_start_pause
            continue
        }
        if {$pin eq "caution"} {
            puts stderr "$::XHC(prog): button $name: 'caution' skipped"
            continue
        }
        if {![pin_exists xhc-hb04.button-$name] || ![pin_exists $pin]} {
            puts stderr "$::XHC(prog): button $name = $pin: pin missing, skipped"
            continue
        }
        xhc_net pendant:$name xhc-hb04.button-$name $pin
    }
}

# Pendant index and label of each coordinate: x y z a keep their own, others take the rest.
proc xhc_map_coords {coords} {
    set labels {x y z a}
    set free [lsearch -all -inline -not -regexp $labels "^([join $coords |])$"]
    set map {}
    foreach letter $coords {
        set idx [lsearch -exact $labels $letter]
        if {$idx < 0} {
            set label [lindex $free 0]
            set free [lrange $free 1 end]
            set idx [lsearch -exact $labels $label]
            puts "$::XHC(prog): coordinate $letter uses the pendant's $label position"
        }
        lappend map [list $letter $idx [lindex $labels $idx]]
    }
    return $map
}

# Jog-accel fraction for a section: mpg_accel / MAX_ACCELERATION (1.0 without mpg_accels).
proc xhc_accel_fraction {section accel} {
    upvar #0 $section arr
    if {$accel eq "" || ![info exists arr(MAX_ACCELERATION)]} { return 1.0 }
    return [expr {abs($accel) / double([lindex $arr(MAX_ACCELERATION) end])}]
}

# Wheel, jog and DRO connections of one coordinate.
proc xhc_coordinate {letter idx label pos coefs scales accels vnormal} {
    set coef [expr {abs([lindex [concat $coefs 1.0 1.0 1.0 1.0] $pos])}]
    if {$coef > 1} { set coef .5 }
    set scale [lindex [concat $scales 1.0 1.0 1.0 1.0] $pos]
    xhc_setp pendant_util.coef$idx $coef
    xhc_setp pendant_util.scale$idx [expr {100 * $scale}]
    set L [string toupper $letter]
    set targets [list axis.$letter]
    if {![catch {joint_number_for_axis $letter} joint]} { lappend targets joint.$joint }
    foreach target $targets {
        set section [expr {[string match axis.* $target] ? "AXIS_$L" : "JOINT_$joint"}]
        xhc_setp $target.jog-accel-fraction [xhc_accel_fraction $section [lindex $accels $pos]]
        if {$vnormal} { xhc_setp $target.jog-vel-mode 1 }
    }
    if {$::XHC(pass0)} return
    xhc_net_out halui.axis.$letter.pos-feedback pendant:pos-$letter xhc-hb04.$label.pos-absolute
    xhc_net_out halui.axis.$letter.pos-relative pendant:pos-rel-$letter \
        xhc-hb04.$label.pos-relative
    set counts {}
    set enables {}
    set jscales {}
    foreach target $targets {
        lappend counts $target.jog-counts
        lappend enables $target.jog-enable
        lappend jscales $target.jog-scale
    }
    xhc_net pendant:wheel-counts-$letter-filtered pendant_util.out$idx {*}$counts
    xhc_net pendant:jog-$letter xhc-hb04.jog.enable-$label {*}$enables
    xhc_net pendant:jog-scale {*}$jscales
    xhc_net pendant:wheel-counts pendant_util.in$idx
}

# Connections shared by all coordinates: wheel scale and counts, overrides, feed and spindle.
proc xhc_common {} {
    xhc_setp pendant_util.k 100.0
    xhc_setp halui.feed-override.scale 0.01
    xhc_setp halui.spindle.0.override.scale 0.01
    if {$::XHC(pass0)} return
    xhc_net pendant:jog-prescale xhc-hb04.jog.scale pendant_util.divide-by-k-in
    xhc_net pendant:jog-scale pendant_util.divide-by-k-out
    xhc_net pendant:wheel-counts xhc-hb04.jog.counts halui.feed-override.counts \
        halui.spindle.0.override.counts
    xhc_net pendant:wheel-counts-neg xhc-hb04.jog.counts-neg
    xhc_net pendant:feed-override-enable xhc-hb04.jog.enable-feed-override \
        halui.feed-override.count-enable
    xhc_net pendant:spindle-override-enable xhc-hb04.jog.enable-spindle-override \
        halui.spindle.0.override.count-enable
    xhc_net_out motion.current-vel pendant:feed-value xhc-hb04.feed-value
    xhc_net_out spindle.0.speed-out-rps-abs pendant:spindle-rps xhc-hb04.spindle-rps
    xhc_net_out halui.max-velocity.value pendant:jog-speed
    xhc_net_out halui.feed-override.value pendant:feed-override xhc-hb04.feed-override
    xhc_net_out halui.spindle.0.override.value pendant:spindle-override \
        xhc-hb04.spindle-override
}

# Read and check the configuration, start the pendant component, connect everything.
proc xhc_main {} {
    if {![array exists ::XHC_HB04_CONFIG]} { xhc_fail "Missing stanza: \[XHC_HB04_CONFIG\]" }
    if {![array exists ::XHC_HB04_BUTTONS]} { xhc_fail "Missing stanza: \[XHC_HB04_BUTTONS\]" }
    if {![info exists ::HAL(HALUI)] || [lindex $::HAL(HALUI) end] eq ""} {
        xhc_fail "\[HAL\]HALUI is not set"
    }
    set layout [xhc_value XHC_HB04_CONFIG layout 2]
    set cfg [switch -- $layout {
        1 { list LIB:xhc-hb04-layout1.cfg }
        2 { list LIB:xhc-hb04-layout2.cfg }
        default { list $layout }
    }]
    set cfg [find_file_in_hallib_path [lindex $cfg 0]]
    set coords [string tolower [xhc_value XHC_HB04_CONFIG coords "x y z a"]]
    set jogmode [xhc_value XHC_HB04_CONFIG jogmode normal]
    if {$jogmode ni {normal vnormal}} {
        xhc_popup "jogmode '$jogmode' is not normal or vnormal; using normal"
        set jogmode normal
    }
    set opts {}
    if {[xhc_value XHC_HB04_CONFIG require_pendant yes] ne "no"} { lappend opts -x }
    set sequence [xhc_value XHC_HB04_CONFIG sequence ""]
    if {$sequence ne ""} { lappend opts -s $sequence }
    if {[catch {loadusr -W xhc-hb04 {*}$opts -I $cfg -H} msg]} {
        xhc_popup "Problem loading xhc-hb04: $msg\nContinuing without xhc-hb04"
        return
    }
    if {[string match in* [xhc_value XHC_HB04_CONFIG inch_or_mm mm]]} {
        xhc_setp xhc-hb04.inch-icon 1
    }
    if {[llength $coords] > 4 || [llength [lsort -unique $coords]] != [llength $coords]} {
        xhc_fail "coords '$coords': at most four different axis letters"
    }
    loadrt xhc_hb04_util names=pendant_util
    addf pendant_util [xhc_value XHC_HB04_CONFIG threadname servo-thread]
    if {!$::XHC(pass0)} { xhc_buttons }
    xhc_common
    set coefs [xhc_value XHC_HB04_CONFIG coefs ""]
    set scales [xhc_value XHC_HB04_CONFIG scales ""]
    set accels [xhc_value XHC_HB04_CONFIG mpg_accels ""]
    set pos 0
    foreach item [xhc_map_coords $coords] {
        lassign $item letter idx label
        xhc_coordinate $letter $idx $label $pos $coefs $scales $accels \
            [expr {$jogmode eq "vnormal"}]
        incr pos
    }
    if {[llength $::XHC(failures)]} {
        xhc_popup "Failed to make some required connections:\n[join $::XHC(failures) \n]"
    }
}

xhc_main
