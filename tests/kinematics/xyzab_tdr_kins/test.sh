#!/bin/bash
# xyzab_tdr_kins through the fake-HAL harness: pins, identity and TCP types, geometry pins.
exec "$EMC2_HOME/objects/unit/comptest" < script
