#!/bin/bash
# three21kins through the fake-HAL harness: pins, defaults, forward/inverse, switching, bad arguments.
exec "$EMC2_HOME/objects/unit/comptest" < script
