#!/bin/bash
# Command-line (argv) mode: exit status, no substitution, arrows and "name = value", options.
realtime start 2> /dev/null || exit 1
run() { echo "> halcmd $*"; halcmd "$@" 2>&1; echo "exit $?"; }
run newsig 'a$b' float
run list sig
run newsig s1 u32
run s1 = 5
run sets s1 7
run gets s1
run gets 's1 # not a comment'
run frobnicate
run quit
run newsig
run newsig a b c
run getp
run sets s1 7 "" ignored words
run gets s1
run -f /nonexistent/file.hal
run -i foo.ini gets s1
run -Z
run -Q status
run -Q gets s1
run status lock
run status nope
run -h newsig
run help gets
run -h frob
run -R
run debug 3
run debug 9
run debug x
echo "> halcmd (no arguments)"
halcmd | head -1
echo "> COMP_LINE completion"
COMP_LINE="halcmd gets s" COMP_POINT=13 halcmd -C
COMP_LINE="halcmd new" COMP_POINT=10 halcmd -C
realtime stop
