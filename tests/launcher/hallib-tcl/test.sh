#!/bin/bash
# The Tcl parts of the HAL library that need no motion stack: hal_procs_lib.tcl and
# util_lib.tcl procedures, basic_sim.tcl's INI checks, xhc-hb04.tcl without its sections and
# without the pendant program.
export HALLIB_DIR=$EMC2_HOME/lib/hallib
realtime start 2> /dev/null || exit 1
# run ARGS: haltcl ARGS, with paths made relative
run() {
    echo "== $*" | sed -e "s|$HALLIB_DIR|<hallib>|g"
    haltcl "$@" 2>&1 | sed -e "s|$PWD/||g" -e "s|$EMC2_HOME|<top>|g"
    echo "exit ${PIPESTATUS[0]}"
}
run procs.tcl
halcmd unload all
run -i no-coordinates.ini $HALLIB_DIR/basic_sim.tcl
run -i lathe-kins.ini $HALLIB_DIR/basic_sim.tcl
run -i nostanza.ini $HALLIB_DIR/xhc-hb04.tcl
run -i nopendant.ini $HALLIB_DIR/xhc-hb04.tcl
halcmd unload all
realtime stop
