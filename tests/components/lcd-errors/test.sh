#!/bin/bash
# Bad lcd format strings fail the load with a message naming the display, page and place.
for a in "" "fmt_strings=" 'fmt_strings=ok|%5.2q' 'fmt_strings=a,b|c\x' 'fmt_strings=%41d' \
    'fmt_strings=%.10f' 'fmt_strings=%bY' 'fmt_strings=abc\' 'fmt_strings=%' 'fmt_strings=\4' \
    'fmt_strings=%40.9f|%bYN\7C\2C'; do
    echo "== $a"
    echo "load lcd $a" | "$EMC2_HOME/objects/unit/comptest"
done
