#!/bin/bash
# show and list in normal and -s script format: every section, patterns and -t type filters.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
halcmd -f setup.hal || exit 1
for opt in "" -s; do
    for what in "pin" "pin and2.0" "pin -tbit" "pin -t float sum" "pin -tbogus toggle.1" \
                "sig" "sig -t bit" "param" "param *.tmax" "param -ts32" "alias" "funct" \
                "thread" "sig ch*"; do
        echo "> halcmd $opt show $what"
        halcmd $opt show $what | sed -e 's/ [0-9a-f]\{8,16\}  *[0-9a-f]\{8,16\} / CODE ARG /'
    done
done
halcmd show comp | grep -v halcmd
halcmd -s show comp | grep -v halcmd
for what in "pin" "pin and2.1" "sig" "param sum" "funct" "thread" "signal" "parameter" "function"; do
    echo "> halcmd list $what"
    halcmd list $what
done
halcmd list comp | tr ' ' '\n' | grep -v '^halcmd' | tr '\n' ' '; echo
halcmd show bogus 2>&1
halcmd list bogus 2>&1
halcmd list 2>&1
halcmd -Q show pin
halcmd -Q list pin
halcmd -Q save
echo "(nothing above with -Q)"
realtime stop
