#!/bin/bash
# HALFILE search: LIB:name in the HAL library, absolute paths as given, relative names over
# HALLIB_PATH (-H dirs first, then the INI directory, then the library); what cannot be found
# stops the launch. halcmd resolves LIB: in -f and in source through $HALLIB_DIR.
export PATH=$PATH:$(cd ../doubles && pwd)
run() {
    echo "== linuxcnc $*"
    linuxcnc -r "$@" > run.out 2> run.err
    echo "exit status $?"
    grep -hv -e "^Note: " -e "^$" -e "^Waiting for component" run.out run.err | sed -e "s|$PWD/||g" -e "s|$PWD|<dir>|g" \
        -e "s|$EMC2_HOME|<top>|g"
}
run -H hdir test.ini
run test.ini
run -H nodir test.ini
run nolib.ini
run illformed.ini
python3 ../common/leftovers.py
echo "== halcmd -f LIB:outer.hal"
realtime start 2> /dev/null
HALLIB_DIR=$PWD/fakelib halcmd -f LIB:outer.hal 2>&1 | sed -e "s|$PWD/||g"
halcmd -f LIB:no-such-file.hal 2>&1 | sed -e "s|$EMC2_HOME|<top>|g"
realtime stop
echo "== linuxcnc_var"
linuxcnc_var HALLIB_DIR | sed -e "s|$EMC2_HOME|<top>|g"
linuxcnc_var NO_SUCH_VAR > /dev/null 2>&1; echo "unknown: exit status $?"
