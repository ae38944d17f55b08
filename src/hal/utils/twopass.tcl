# twopass.tcl: load a configuration's [HAL]HALFILEs in two passes (run by `haltcl -i INI twopass.tcl`).
# Pass 0 collects every loadrt (merging repeated loads of one module into a single load) and runs
# loadusr; the merged loads are then made. Pass 1 runs everything else, file by file, in order.
# .hal files go line by line through halcmd's parser; .tcl files are sourced in both passes with
# ::tp::passnumber telling them which one it is. [HAL]TWOPASS words: verbose, nodelete.

namespace eval ::tp {
    variable pass 0
    variable verbose 0
    variable modules {}          ;# module names in first-load order
    variable loads               ;# loads(<module>) = list of argument lists
    variable hal_commands {}
}

# The current pass (0 or 1); hallib .tcl files test it.
proc ::tp::passnumber {} {
    return $::tp::pass
}

# Silence puts (used by files that are quiet in pass 0).
proc ::tp::no_puts {} {
    if {[info commands ::tp::real_puts] eq ""} { rename ::puts ::tp::real_puts }
    proc ::puts {args} {}
}

# Prefix every puts to stdout with "<passN> ".
proc ::tp::alter_puts {} {
    if {[info commands ::tp::real_puts] eq ""} { rename ::puts ::tp::real_puts }
    proc ::puts {args} {
        if {[llength $args] == 1} {
            return [::tp::real_puts "<pass$::tp::pass> [lindex $args 0]"]
        }
        return [::tp::real_puts {*}$args]
    }
}

# Undo no_puts / alter_puts.
proc ::tp::restore_puts {} {
    if {[info commands ::tp::real_puts] ne ""} {
        rename ::puts {}
        rename ::tp::real_puts ::puts
    }
}

# Progress text when [HAL]TWOPASS contains "verbose".
proc ::tp::say {text} {
    if {$::tp::verbose} { puts "twopass: $text" }
}

# Report a fatal problem (also appended to $PRINT_FILE when the launcher keeps one) and stop.
proc ::tp::fail {text} {
    puts stderr $text
    if {[info exists ::env(PRINT_FILE)]} {
        catch {
            set f [open $::env(PRINT_FILE) a]
            puts $f $text
            close $f
        }
    }
    exit 1
}

# find_file_in_hallib_path: LIB:name -> $HALLIB_DIR/name; absolute as is; else ./name, $HALLIB_DIR/name.
proc ::tp::find_file {name} {
    set libdir [expr {[info exists ::env(HALLIB_DIR)] ? $::env(HALLIB_DIR) : ""}]
    if {[string match LIB:* $name]} {
        set candidates [list [file join $libdir [string range $name 4 end]]]
    } elseif {[file pathtype $name] eq "absolute"} {
        set candidates [list $name]
    } else {
        set candidates [list [file join . $name] [file join $libdir $name]]
    }
    foreach path $candidates {
        if {[file isfile $path] && [file readable $path]} { return $path }
    }
    return ""
}

# The HALFILE entries as {path args} pairs; unknown files or types stop the load.
proc ::tp::halfiles {} {
    set found {}
    if {![info exists ::HAL(HALFILE)]} { return $found }
    foreach entry $::HAL(HALFILE) {
        set name [lindex $entry 0]
        set path [find_file $name]
        if {$path eq ""} { fail "twopass:CANNOT FIND FILE FOR:$name" }
        puts "twopass:found $path"
        if {[file extension $path] ni {.hal .tcl}} {
            fail "prep_the_files:unknown file type $path"
        }
        lappend found [list $path [lrange $entry 1 end]]
    }
    return $found
}

# Logical lines of a .hal file as {last-line-number text} (backslash continuation joined).
proc ::tp::hal_lines {path} {
    set f [open $path r]
    set lines [split [read $f] "\n"]
    close $f
    set result {}
    set pending ""
    set number 0
    foreach line $lines {
        incr number
        if {[string index $line end] eq "\\"} {
            append pending [string range $line 0 end-1]
            continue
        }
        lappend result [list $number "$pending$line"]
        set pending ""
    }
    if {$pending ne ""} { lappend result [list $number $pending] }
    return $result
}

# The command word of a HAL line (first word before any comment), "" for none.
proc ::tp::command_word {text} {
    set text [string trim $text]
    if {$text eq "" || [string index $text 0] eq "#"} { return "" }
    return [lindex [regexp -inline {^\S+} $text] 0]
}

# Does a .hal file ask to be run as a whole, once (#NOTWOPASS)?
proc ::tp::notwopass {path} {
    foreach item [hal_lines $path] {
        if {[string match "#NOTWOPASS*" [string trimleft [lindex $item 1]]]} { return 1 }
    }
    return 0
}

# Remember one loadrt request (words after "loadrt") for the merged load.
proc ::tp::collect {words} {
    variable modules
    variable loads
    if {[llength $words] == 0} return
    set mod [lindex $words 0]
    if {$mod ni $modules} { lappend modules $mod }
    lappend loads($mod) [lrange $words 1 end]
}

# The merged "loadrt" words of one module: count=/num_chan= summed, names=/personality= joined,
# debug= ORed, other arguments kept (the last value wins).
proc ::tp::merged {mod} {
    variable loads
    set form ""
    set count 0
    set bare 0
    set names {}
    set personality {}
    set debug ""
    set other [dict create]
    foreach arglist $loads($mod) {
        set has_form 0
        foreach arg $arglist {
            lassign [split_arg $arg] key value
            switch -- $key {
                count - num_chan - names {
                    set this [expr {$key eq "names" ? "names" : $key}]
                    if {$form ne "" && $form ne $this} {
                        fail "loadrt_substitute: cannot mix count=, num_chan= and names= forms\
                              for module '$mod'"
                    }
                    set form $this
                    set has_form 1
                    if {$key eq "names"} {
                        foreach n [split $value ,] { if {$n ne ""} { lappend names $n } }
                    } elseif {[catch {incr count [expr {int($value)}]}]} {
                        fail "loadrt_substitute: module '$mod': $key=$value is not a number"
                    }
                }
                personality { lappend personality $value }
                debug { set debug [expr {($debug eq "" ? 0 : $debug) | $value}] }
                default { dict set other $key $arg }
            }
        }
        if {!$has_form} { incr bare }
    }
    set words [list loadrt $mod]
    if {$form eq "names"} {
        lappend words "names=[join $names ,]"
    } elseif {$form ne ""} {
        lappend words "$form=[expr {$count + $bare}]"
    }
    if {[llength $personality]} { lappend words "personality=[join $personality ,]" }
    if {$debug ne ""} { lappend words "debug=$debug" }
    dict for {key arg} $other { lappend words $arg }
    return $words
}

# "key=value" -> {key value}; a word without '=' -> {word ""}.
proc ::tp::split_arg {arg} {
    set eq [string first = $arg]
    if {$eq < 0} { return [list $arg ""] }
    return [list [string range $arg 0 [expr {$eq - 1}]] [string range $arg [expr {$eq + 1}] end]]
}

# Run one .hal line through halcmd's parser; a failure stops the load with its file:line text.
proc ::tp::hal_line {path number text} {
    if {[catch {hal --line $path $number $text} out]} { fail $out }
    if {$out ne ""} { puts $out }
}

# One pass over a .hal file: pass 0 collects loadrt and runs loadusr, pass 1 runs the rest.
proc ::tp::hal_file {path} {
    foreach item [hal_lines $path] {
        lassign $item number text
        set word [command_word $text]
        if {$::tp::pass == 0 && $word eq "loadrt"} {
            if {[catch {hal --substitute $text} expanded]} { fail "$path:$number: $expanded" }
            collect [lrange [regexp -all -inline {\S+} $expanded] 1 end]
        } elseif {$::tp::pass == 0 && $word eq "loadusr"} {
            hal_line $path $number $text
        } elseif {$::tp::pass == 1 && $word ni {loadrt loadusr ""}} {
            hal_line $path $number $text
        }
    }
}

# One pass over a .tcl file, sourced with its HALFILE arguments as ::argv.
proc ::tp::tcl_file {path arguments} {
    set ::argv $arguments
    set ::argc [llength $arguments]
    if {[catch {uplevel #0 [list ::haltcl::tcl_source $path]} err options]} {
        fail [::haltcl::error_location $path $options $err]
    }
}

# What a HAL command does during a pass: pass 0 only loads, pass 1 does all but loading.
proc ::tp::dispatch {cmd arglist} {
    if {$::tp::pass == 0} {
        switch -- $cmd {
            loadrt { collect $arglist; return }
            loadusr { return [::tp::real::loadusr {*}$arglist] }
            default { return }
        }
    }
    if {$cmd in {loadrt loadusr}} return
    return [::tp::real::$cmd {*}$arglist]
}

# Route haltcl's HAL commands (and `source` of .hal files) through ::tp::dispatch.
proc ::tp::intercept {} {
    namespace eval ::tp::real {}
    foreach cmd [hal --commands] {
        if {[info commands ::$cmd] eq "" || $cmd in {source list gets}} continue
        rename ::$cmd ::tp::real::$cmd
        proc ::$cmd {args} [format {return [::tp::dispatch %s $args]} $cmd]
    }
    proc ::source {args} {
        if {[llength $args] == 1 && [string match *.hal [lindex $args 0]]} {
            return [::tp::hal_file [lindex $args 0]]
        }
        return [uplevel 1 [list ::haltcl::tcl_source {*}$args]]
    }
}

# One pass over every file; #NOTWOPASS .hal files run whole, once, in pass 0.
proc ::tp::run_pass {files} {
    foreach item $files {
        lassign $item path arguments
        say "pass $::tp::pass: $path"
        if {[file extension $path] eq ".tcl"} {
            tcl_file $path $arguments
        } elseif {[notwopass $path]} {
            if {$::tp::pass == 0} {
                if {[catch {hal source $path} out]} { fail $out }
                if {$out ne ""} { puts $out }
            }
        } else {
            hal_file $path
        }
    }
}

# Load the merged modules after pass 0.
proc ::tp::load_modules {} {
    foreach mod $::tp::modules {
        set words [merged $mod]
        say [join $words]
        if {[catch {hal {*}$words} err]} { fail "twopass: [join $words]: $err" }
    }
}

# Entry point: both passes over [HAL]HALFILE.
proc ::tp::main {} {
    set mode [expr {[info exists ::HAL(TWOPASS)] ? [join $::HAL(TWOPASS)] : ""}]
    set ::tp::verbose [expr {"verbose" in $mode}]
    if {"nodelete" in $mode} {
        say "nodelete: .hal files are read in place, no temporary files are made"
    }
    set files [halfiles]
    intercept
    set ::tp::pass 0
    run_pass $files
    load_modules
    set ::tp::pass 1
    run_pass $files
}

::tp::main
