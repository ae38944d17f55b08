# hal_procs_lib.tcl: procedures for HAL Tcl files that inspect the running HAL (pins, signals,
# threads) through `hal show`/`hal list`, and find files like the launcher does.

package require Hal

# 1 when a pin of exactly this name exists.
proc pin_exists {name} {
    return [expr {[lindex [hal list pin $name] 0] eq $name}]
}

# Fill arr(owner,type,direction,value,separator,signame) from the pin's `show pin` line;
# 0 when the pin does not exist.
proc connection_info {aname pinname} {
    upvar $aname ay
    foreach line [split [hal show pin $pinname] "\n"] {
        if {[lindex $line 4] ne $pinname} continue
        foreach key {owner type direction value name separator signame} word $line {
            set ay($key) $word
        }
        unset ay(name)
        return 1
    }
    return 0
}

# is_input / is_output / is_io for a linked pin (as seen from the pin), else not_connected;
# the signal name goes to sigvar when given.
proc is_connected {pinname {sigvar ""}} {
    if {$sigvar ne ""} {
        upvar $sigvar signame
    }
    set signame ""
    if {![connection_info info $pinname]} { return not_connected }
    set signame $info(signame)
    switch -- $info(separator) {
        "<==" { return is_input }
        "==>" { return is_output }
        "<=>" { return is_io }
    }
    return not_connected
}

# Parse `hal show thread` into arr: threadnames, (T,fp), (T,period), (T,<funct>) = index,
# (T,index,last); and where motion-command-handler / motion-controller run. Returns the thread
# holding motion-controller.
proc thread_info {aname} {
    upvar $aname ay
    set ay(threadnames) {}
    set thread ""
    foreach line [lrange [split [hal show thread] "\n"] 2 end] {
        if {[llength $line] >= 3 && [string is integer -strict [lindex $line 0]] &&
            [lindex $line 1] in {YES NO}} {
            set thread [lindex $line 2]
            lappend ay(threadnames) $thread
            set ay($thread,period) [lindex $line 0]
            set ay($thread,fp) [lindex $line 1]
            set ay($thread,index,last) 0
        } elseif {[llength $line] == 2 && $thread ne ""} {
            lassign $line index funct
            set ay($thread,$funct) $index
            set ay($thread,index,last) $index
            if {$funct in {motion-command-handler motion-controller}} {
                set ay($funct,threadname) $thread
                set ay($funct,index) $index
            }
        }
    }
    if {[info exists ay(motion-command-handler,threadname)]} {
        if {![info exists ay(motion-controller,threadname)]} {
            return -code error "thread_info: motion-controller is not on any thread"
        }
        if {$ay(motion-command-handler,threadname) ne $ay(motion-controller,threadname)} {
            return -code error "thread_info: motion-command-handler and motion-controller\
                                are on different threads"
        }
    }
    if {[info exists ay(motion-controller,threadname)]} {
        return $ay(motion-controller,threadname)
    }
    return ""
}

# From `hal show signal sig`: reader pins into invar, the writer into outvar, IO pins into iovar.
proc get_netlist {inpinsvar outpinvar iopinsvar signame} {
    upvar $inpinsvar inpins $outpinvar outpin $iopinsvar iopins
    set inpins {}
    set outpin {}
    set iopins {}
    foreach line [split [hal show signal $signame] "\n"] {
        if {[llength $line] != 2} continue
        lassign $line arrow pin
        switch -- $arrow {
            "==>" { lappend inpins $pin }
            "<==" { lappend outpin $pin }
            "<=>" { lappend iopins $pin }
        }
    }
}

# Where a file named in a HAL context is: LIB:name in $HALLIB_DIR, an absolute name as it is,
# else inidir/name, then $HALLIB_DIR/name.
proc find_file_in_hallib_path {filename {inidir .}} {
    set libdir [expr {[info exists ::env(HALLIB_DIR)] ? $::env(HALLIB_DIR) : ""}]
    if {[string match LIB:* $filename]} {
        set candidates [list [file join $libdir [string range $filename 4 end]]]
    } elseif {[file pathtype $filename] eq "absolute"} {
        set candidates [list $filename]
    } else {
        set candidates [list [file join $inidir $filename] [file join $libdir $filename]]
    }
    foreach path $candidates {
        if {[file readable $path] && [file isfile $path]} { return $path }
    }
    return -code error "find_file_in_hallib_path: cannot find: <$filename>"
}
