#!/bin/bash
# xyzac-trt-kins through the fake-HAL harness: pins, TCP math, switching, coordinates errors.
for script in script1 script2 script3 script4 script5; do
    "$EMC2_HOME/objects/unit/comptest" < "$script"
done
