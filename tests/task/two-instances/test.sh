#!/bin/bash
# Two configurations at once: machine B is started (in an instance the launcher picks) while
# machine A runs; each is homed and moved, neither disturbs the other, both shut down cleanly.
. ../lib/run-machine.sh
rm -f b.out b.log
run_machine || { cat b.log 2>/dev/null >&2; exit 1; }
rm -f b.out b.log b.var b.var.bak
