#!/bin/bash
# Motion segment logic without HAL: ring order and full ring, NaN refusal, seqlock, message queue, echo lookup.
exec "$EMC2_HOME/objects/unit/motion_shm_unit"
