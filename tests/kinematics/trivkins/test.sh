#!/bin/bash
# trivkins through the fake-HAL harness: joint maps, types and coordinate errors.
exec "$EMC2_HOME/objects/unit/comptest" < script
