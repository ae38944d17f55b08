#!/bin/bash
# millturn through the fake-HAL harness; a second run checks that coordinates= (not a millturn argument) fails.
"$EMC2_HOME/objects/unit/comptest" < script
echo "coordinates= is not an argument of millturn"
echo "load millturn coordinates=xyzc" | "$EMC2_HOME/objects/unit/comptest"
