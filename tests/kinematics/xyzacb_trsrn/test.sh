#!/bin/bash
# xyzacb_trsrn through the fake-HAL harness: pins, identity and TCP types, head and table math.
exec "$EMC2_HOME/objects/unit/comptest" < script
