#!/bin/bash
# Every supported element kind evaluated by the scan (contacts, edges, coils, set/reset, timers,
# monostable, IEC timer, counter, compare, operate on words and floats, jump, subroutine call).
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cl_sim" < script
