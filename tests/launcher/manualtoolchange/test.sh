#!/bin/bash
# hal_manualtoolchange with neither an X display nor a terminal: a tool change is confirmed at
# once (with a note), and changed follows change back to FALSE.
unset DISPLAY
realtime start 2> /dev/null || exit 1
# wait_pin PIN VALUE: until PIN shows VALUE (at most 5 s)
wait_pin() {
    for i in $(seq 100); do [ "$(halcmd getp $1)" = "$2" ] && return 0; sleep 0.05; done
    echo "timeout: $1 is $(halcmd getp $1), not $2"
}
halcmd loadusr -W hal_manualtoolchange < /dev/null 2> note.err
halcmd setp hal_manualtoolchange.number 7
halcmd setp hal_manualtoolchange.change 1
wait_pin hal_manualtoolchange.changed TRUE
echo "after change=1: changed=$(halcmd getp hal_manualtoolchange.changed)"
halcmd setp hal_manualtoolchange.change 0
wait_pin hal_manualtoolchange.changed FALSE
echo "after change=0: changed=$(halcmd getp hal_manualtoolchange.changed)"
halcmd unload all
sleep 0.3
cat note.err
realtime stop
