#!/bin/bash
# carousel module arguments: instance count from pockets= (or names=), entries inherited from the
# previous carousel, an unknown encoding reported and ignored, sense pins per encoding, refusals.
# For each load: the messages, then every funct with the number of its sense pins.
run() {
    echo "== $*"
    local out
    out=$(printf '%s\n' "load carousel $*" show | "$EMC2_HOME/objects/unit/comptest")
    grep -E "^rtapi_app_main|^carousel:" <<<"$out"
    for f in $(grep -oP "^funct \K.*" <<<"$out"); do
        echo "$f: $(grep -c "^pin bit IN $f\.sense-" <<<"$out") sense pins"
    done
}
run ""
run pockets=6,10,0,12
run "pockets=6,10 encoding=index,single"
run "pockets=8 encoding=bcd num_sense=8"
run "pockets=8 encoding=grey"
run "pockets=4,4 encoding=binary,sideways num_sense=3"
run "pockets=8,12 encoding=edge,counts num_sense=1"
run "pockets=40 encoding=single"
run "pockets=8 num_sense=33"
run "names=left,right pockets=6"
run "names=left,,right"
