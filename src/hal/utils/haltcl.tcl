#!/usr/bin/env tclsh
# haltcl: Tcl whose HAL commands (loadrt, net, setp, ...) run in-process through package Hal,
# with the INI file's sections as global arrays ::SECTION(KEY) (each value one list element).

namespace eval ::haltcl {
    variable bindir [file dirname [file normalize [info script]]]
    # commands whose text output is printed (as halcmd prints it) rather than returned
    variable printing {show save status help echo unecho}
    # Tcl built-ins that keep their Tcl meaning; use `hal list`, `hal gets`
    variable tcl_owned {list gets source}
}

# Make package Hal findable from the tree (bin/../lib/tcl) and set HALLIB_DIR when unset.
proc ::haltcl::setup_paths {} {
    variable bindir
    set top [file dirname $bindir]
    lappend ::auto_path [file join $top lib tcl]
    if {![info exists ::env(HALLIB_DIR)] && [file isdirectory [file join $top lib hallib]]} {
        set ::env(HALLIB_DIR) [file join $top lib hallib]
    }
}

# Evaluate a setp/sets value as a Tcl expression (".07" -> 0.07); anything else stays as given.
proc ::haltcl::value {text} {
    if {[catch {expr $text} result]} {
        return $text
    }
    return $result
}

# Define one Tcl command per HAL command, forwarding to `hal`.
proc ::haltcl::define_commands {} {
    variable printing
    variable tcl_owned
    foreach cmd [hal --commands] {
        if {$cmd in $tcl_owned} continue
        if {$cmd in {setp sets}} {
            proc ::$cmd {name args} [format {
                if {[llength $args] == 1} {
                    return [hal %s $name [::haltcl::value [lindex $args 0]]]
                }
                return [hal %s $name {*}$args]
            } $cmd $cmd]
        } elseif {$cmd in $printing} {
            proc ::$cmd {args} [format {
                set text [hal %s {*}$args]
                if {$text ne ""} { puts $text }
                return
            } $cmd]
        } else {
            proc ::$cmd {args} [format {return [hal %s {*}$args]} $cmd]
        }
    }
    rename ::source ::haltcl::tcl_source
    proc ::source {args} {
        if {[llength $args] == 1 && [string match *.hal [lindex $args 0]]} {
            return [hal source [lindex $args 0]]
        }
        return [uplevel 1 [list ::haltcl::tcl_source {*}$args]]
    }
}

# Load every INI entry into ::SECTION(KEY), appending each value as one list element.
proc ::haltcl::read_ini {path} {
    foreach {section key value} [hal --ini-entries $path] {
        upvar #0 $section arr
        lappend arr($key) $value
    }
    hal --ini $path
}

# Refuse an INI file other than the one the launcher exported as INI_FILE_NAME.
proc ::haltcl::check_ini_name {path} {
    if {![info exists ::env(INI_FILE_NAME)] || $::env(INI_FILE_NAME) eq ""} return
    if {[file normalize $path] ne [file normalize $::env(INI_FILE_NAME)]} {
        puts stderr "parse_ini: fatal: requested filename ($path) and\
                     env(INI_FILE_NAME) ($::env(INI_FILE_NAME)) are not the same."
        exit 1
    }
}

# "file:line: message" for an error raised while sourcing a file (innermost file named).
proc ::haltcl::error_location {file options message} {
    set info [dict get $options -errorinfo]
    set prefix "$file: "
    if {[regexp {\(file "([^"]+)" line (\d+)\)} $info -> where line]} {
        set prefix "$where:$line: "
    }
    set lines {}
    foreach text [split $message "\n"] { lappend lines "$prefix$text" }
    return [join $lines "\n"]
}

# Read Tcl commands from stdin (prompting on a terminal) and run them.
proc ::haltcl::interactive {} {
    set tty [expr {![catch {fconfigure stdin -mode}]}]
    set cmd ""
    while {1} {
        if {$tty} {
            puts -nonewline [expr {$cmd eq "" ? "haltcl: " : "haltcl+: "}]
            flush stdout
        }
        if {[gets stdin line] < 0} break
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

# haltcl [-i|-ini INI] [file [args...]]
proc ::haltcl::main {arguments} {
    setup_paths
    if {[catch {package require Hal} err]} {
        puts stderr "haltcl: cannot load package Hal: $err"
        exit 1
    }
    define_commands
    if {[lindex $arguments 0] in {-i -ini}} {
        if {[llength $arguments] < 2} {
            puts stderr "haltcl: [lindex $arguments 0] needs an INI file name"
            exit 1
        }
        set ini [lindex $arguments 1]
        check_ini_name $ini
        if {[catch {read_ini $ini} err]} {
            puts stderr "haltcl: cannot read INI file: $err"
            exit 1
        }
        set arguments [lrange $arguments 2 end]
    }
    if {[llength $arguments] == 0} {
        interactive
        exit 0
    }
    set file [lindex $arguments 0]
    set ::argv [lrange $arguments 1 end]
    set ::argc [llength $::argv]
    if {[catch {uplevel #0 [list source $file]} err options]} {
        puts stderr [error_location $file $options $err]
        exit 1
    }
    exit 0
}

fconfigure stdout -buffering line
if {[lindex $argv 0] in {--help -h}} {
    puts "Usage: haltcl \[-i INIFILE\] \[FILE.tcl \[args...\]\]"
    puts "Tcl with the HAL commands (loadrt, net, setp, ...) as Tcl commands; with -i, INIFILE's"
    puts "sections are Tcl arrays (\$::KINS(JOINTS)). Without FILE an interactive prompt reads commands."
    exit 0
}
::haltcl::main $argv
