#!/bin/bash
# bad-instance: OPENEMC_INSTANCE outside 0..16777215 (or not a number) is refused by every entry
# point instead of folding onto another session; 255, 256, 5110 and 007 are accepted.
for value in 16777216 123456789 -1 abc 1e3 " 7"; do
    echo "> OPENEMC_INSTANCE='$value'"
    OPENEMC_INSTANCE=$value realtime start 2>&1; echo "realtime start -> $?"
    OPENEMC_INSTANCE=$value realtime status 2>&1; echo "realtime status -> $?"
    OPENEMC_INSTANCE=$value rtapi_app ping 2>&1; echo "rtapi_app ping -> $?"
    OPENEMC_INSTANCE=$value halcmd show comp 2>&1 | head -3; echo "halcmd -> ${PIPESTATUS[0]}"
    OPENEMC_INSTANCE=$value python3 -c 'import hal; hal.component("x")' 2>&1 | tail -1
done
echo "> accepted values (no complaint; whether a master runs there does not matter)"
for value in 255 256 5110 16777215 007 ""; do
    echo "'$value': $(OPENEMC_INSTANCE=$value realtime status 2>&1 | grep -c 'not an instance')"
done
