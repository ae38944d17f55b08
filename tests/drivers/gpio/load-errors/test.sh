#!/bin/bash
# load-errors: hal_gpio refuses bad argument lists and lines it cannot find with a clear message,
# loads with no lines at all (read and write functs only), and leaves nothing behind on failure.
log=$(mktemp)
trap 'realtime stop > /dev/null 2>&1; rm -f "$log"' EXIT
realtime start > "$log" 2>&1 || exit 1
seen=$(wc -l < "$log")
# load ARGS...: loadrt hal_gpio ARGS, then its exit status and the master's messages.
load() {
    echo "== $*"
    halcmd loadrt hal_gpio "$@" > /dev/null 2>&1
    echo "status $?"
    tail -n +$((seen + 1)) "$log"
    seen=$(wc -l < "$log")
}
load inputs=a,a
load inputs=a outputs=a
load outputs=b invert=c
load outputs=b opendrain=b opensource=b
load inputs=a pullup=a pulldown=a
load inputs=abcdefghijklmnopqrstuvwxyz0123456789
load inputs=no-such-line-1 outputs=no-such-line-2
load outputs=no-such-line-3
load inputs=x invert=x
echo "components: [$(halcmd list comp hal_gpio)]"
load
halcmd list funct hal_gpio
echo "params: [$(halcmd list param hal_gpio | tr -s ' ' | sed 's/ $//')]"
