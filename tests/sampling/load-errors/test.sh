#!/bin/bash
# load-errors: bad sampler/streamer arguments fail cleanly; good ones give the documented pins.
REALTIME=${REALTIME:-realtime}

# Loads a module with arguments and prints the halcmd exit status.
load() {
    echo "== loadrt $*"
    halcmd loadrt "$@" 2>/dev/null
    echo "exit $?"
}

$REALTIME start 2> master.err
for mod in sampler streamer; do
    load $mod
    load $mod depth=10 cfg=bx
    load $mod depth=10 cfg=ffffffffffffffffffffff
    load $mod cfg=ff
    load $mod depth=10,10 cfg=ff,Q
done
load sampler depth=10 cfg=FRBSULK
load streamer depth=10 cfg=fbsulk
halcmd -s show pin sampler streamer | awk 'NF {print $2, $3, $5}'
halcmd unload sampler
halcmd unload streamer
halcmd -s show pin | awk 'NF {print $2, $3, $5}'
$REALTIME stop
echo "== master messages"
grep -E '^(stream|SAMPLER|STREAMER):' master.err
rm -f master.err
