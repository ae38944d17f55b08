#!/bin/bash
# Two instances (different OPENEMC_INSTANCE) run masters side by side, load the
# same module with different parameters and never see each other.
. ../lib.sh
rt_reserve_instance
other() { OPENEMC_INSTANCE=$rt_other "$@"; }
realtime start
other realtime start
rtapi_app load rtapi_test_params count=1
other rtapi_app load rtapi_test_params count=2
echo "ours:"; rtapi_app list
echo "other:"; other rtapi_app list
other rtapi_app unload rtapi_test_params
echo "ours after the other unloaded:"; rtapi_app list
echo "counter segments: $(ipcs -m | grep -c -e "$(rt_key 0x48484c34)" -e "$(rt_key 0x48484c34 $rt_other)")"
other realtime stop
echo "other stopped; ours answers: $(rtapi_app ping && echo yes)"
echo "other's counter segment left: $(ipcs -m | grep -c "$(rt_key 0x48484c34 $rt_other)")"
echo "ours still has its counter: $(ipcs -m | grep -c "$(rt_key 0x48484c34)")"
realtime stop
