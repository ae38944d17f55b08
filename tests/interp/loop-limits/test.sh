#!/bin/bash
# Runaway loops end with an error at configurable limits ([RS274NGC]MAX_LOOP_ITERATIONS,
# MAX_TOTAL_LOOP_ITERATIONS); the defaults let long valid loops run.
status=0
for f in runaway runaway-nested; do
    want=$(head -n 1 $f.ngc | sed 's/^;//')
    rs274 -g -i small.ini $f.ngc > /dev/null 2> err.txt && status=1
    got=$(tail -n 2 err.txt | head -n 1)
    echo "$f: $got"
    [ "$got" = "$want" ] || status=1
done
rm -f err.txt
rs274 -g long.ngc 2>/dev/null | grep MESSAGE
exit $status
