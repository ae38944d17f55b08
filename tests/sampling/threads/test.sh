#!/bin/bash
# threads: creates threads through the threads module and checks periods and errors.
REALTIME=${REALTIME:-realtime}

# Prints the thread header lines of `show thread` without the time columns.
show_threads() {
    halcmd show thread | sed -e 's/ *(.*)$//' -e '/^$/d'
}

# Loads threads with the given arguments and prints the halcmd exit status.
load() {
    echo "== loadrt threads [$*]"
    halcmd loadrt threads "$@" 2>/dev/null
    echo "exit $?"
    show_threads
}

$REALTIME start 2> master.err
load
halcmd unload threads
load name1=a period1=1000000 name2=b period2=100000
grep -c "THREADS: ERROR: could not create thread 'b'" master.err
load name1=fast period1=1000000 name2=slow period2=2000000 name3=slower period3=5000000
halcmd unload threads
load name1=x period1=6000000 name2= period2=7000000 name3=z period3=0
$REALTIME stop
rm -f master.err
