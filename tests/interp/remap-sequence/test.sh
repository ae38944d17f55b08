#!/bin/bash
# REMAP: a remapped code runs at its modal group's step and the block finishes after the
# procedure returns; its modal group takes part in the same-group check; required words are
# checked first and errors name the generated "O <proc> call" line.
for f in order resume group-m group-g missing-first call-line spindle-off feed-zero; do
    echo "== $f"
    rs274 -i test.ini -g $f.ngc 2> err.txt | awk '{$1=""; print}' | tail -n +7
    echo "exit ${PIPESTATUS[0]}"
    grep -v '^executing$' err.txt
done
rm -f err.txt
exit 0
