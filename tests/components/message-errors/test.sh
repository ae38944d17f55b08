#!/bin/bash
# message: every instance needs a message; missing or empty ones refuse the load.
for a in "count=2 messages=only-one" "names=a,b" "count=1" "count=1 messages=" "count=2 messages=one,two"; do
    echo "== $a"
    printf 'load message %s\n' "$a" | "$EMC2_HOME/objects/unit/comptest"
done
