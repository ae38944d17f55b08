#!/bin/bash
# 5axiskins through the fake-HAL harness: pivot arm math, pins, switching, coordinates errors.
for script in script1 script2 script3; do
    "$EMC2_HOME/objects/unit/comptest" < "$script"
done
