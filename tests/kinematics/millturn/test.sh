#!/bin/bash
# millturn through the fake-HAL harness; more runs check the default map and bad coordinates=.
"$EMC2_HOME/objects/unit/comptest" < script
echo "default coordinates XYZC"
printf 'load millturn\nkinv 4 1 2 3 0 0 7\n' | "$EMC2_HOME/objects/unit/comptest"
echo "joints 0..2 must be XYZ"
echo "load millturn coordinates=zyxc" | "$EMC2_HOME/objects/unit/comptest"
echo "bad letter"
echo "load millturn coordinates=xyzk" | "$EMC2_HOME/objects/unit/comptest"
