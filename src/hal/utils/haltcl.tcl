#!/usr/bin/env tclsh
# haltcl: Tcl with a `hal` command (halcmd in argv mode) and INI values as ::SECTION(KEY) arrays.

# Run one halcmd command; its output is the result, a failure raises an error.
proc hal {args} {
    if {[catch {exec halcmd {*}$args 2>@stderr} out]} {
        return -code error $out
    }
    return $out
}

# Load every [SECTION]KEY=VALUE of an INI file into ::SECTION(KEY); repeated keys form a list.
proc haltcl_read_ini {path} {
    set f [open $path r]
    set section ""
    while {[gets $f line] >= 0} {
        set line [string trim $line]
        if {$line eq "" || [string index $line 0] in {# ;}} continue
        if {[regexp {^\[([^\]]+)\]} $line -> section]} continue
        if {![regexp {^([^=]+)=(.*)$} $line -> key value]} continue
        set key [string trim $key]
        set value [string trim $value]
        upvar #0 $section arr
        if {[info exists arr($key)]} {
            lappend arr($key) $value
        } else {
            set arr($key) [list $value]
        }
    }
    close $f
    foreach name [info globals] {
        upvar #0 $name arr
        if {[array exists arr]} {
            foreach key [array names arr] {
                if {[llength $arr($key)] == 1} { set arr($key) [lindex $arr($key) 0] }
            }
        }
    }
}

# Read Tcl commands from stdin and run them, printing results and errors.
proc haltcl_interactive {} {
    set cmd ""
    while {[gets stdin line] >= 0} {
        append cmd $line "\n"
        if {![info complete $cmd]} continue
        if {[catch {uplevel #0 $cmd} result]} {
            puts stderr $result
        } elseif {$result ne ""} {
            puts $result
        }
        set cmd ""
    }
}

fconfigure stdout -buffering line
set haltcl_args $argv
if {[lindex $haltcl_args 0] in {--help -h}} {
    puts "Usage: haltcl \[-i INIFILE\] \[FILE.tcl \[args...\]\]"
    puts "Tcl with a 'hal' command that runs halcmd commands; with -i, INIFILE's values are the"
    puts "arrays ::SECTION(KEY). Without FILE an interactive prompt reads commands."
    exit 0
}
if {[lindex $haltcl_args 0] eq "-i"} {
    set ::HALTCL_INI [lindex $haltcl_args 1]
    if {[catch {haltcl_read_ini $::HALTCL_INI} err]} {
        puts stderr "haltcl: cannot read INI file: $err"
        exit 1
    }
    set haltcl_args [lrange $haltcl_args 2 end]
}
if {[llength $haltcl_args] == 0} {
    haltcl_interactive
    exit 0
}
set argv0 [lindex $haltcl_args 0]
set argv [lrange $haltcl_args 1 end]
set argc [llength $argv]
if {[catch {uplevel #0 [list source $argv0]} err]} {
    puts stderr "$argv0: $err"
    exit 1
}
exit 0
