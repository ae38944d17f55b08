#!/bin/bash
# $OPENEMC_HAL_SIZE sets the arena size; running out gives clean -ENOMEM errors; a bad value falls back to 32 MiB.
OPENEMC_HAL_SIZE=262144 "$EMC2_HOME/objects/unit/hal_core_arena" 2>&1
OPENEMC_HAL_SIZE=12abc "$EMC2_HOME/objects/unit/hal_core_arena" total-only 2>&1
