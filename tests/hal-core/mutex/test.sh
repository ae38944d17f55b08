#!/bin/bash
# HAL mutex across processes: two concurrent creators, recursion, take-over from a dead holder.
"$EMC2_HOME/objects/unit/hal_core_mutex" 2>&1
