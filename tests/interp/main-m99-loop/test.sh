#!/bin/bash
# M99 in the main program: ends it like M2 in rs274; with task's looping it restarts the program
# (after its opening %) keeping the modal state, until the program's own M2.
"$EMC2_HOME/objects/unit/interp_main_m99_unit" | awk '{$1=""; print}'
exit "${PIPESTATUS[0]}"
