#!/bin/bash
# xyzbc-trt-kins through the fake-HAL harness: pins, TCP math, switching, coordinates errors.
for script in script1 script2 script3; do
    "$EMC2_HOME/objects/unit/comptest" < "$script"
done
