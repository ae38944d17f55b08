#!/bin/bash
# sim_matrix_kb: count= and names= instances (their out pins shown), and the refusal of bad arguments.
run() {
    echo "== $*"
    printf '%s\n' "load sim_matrix_kb $*" show | "$EMC2_HOME/objects/unit/comptest" | grep -v "\.button\."
}
run count=2
run names=pad,panel
for a in count=-1 "count=2 names=a" names=a,,b 'names="a b"' config=2x2; do
    run "$a"
done
