#!/bin/bash
# userkins (a halcompile kinematics template) through the fake-HAL harness, plus an unknown argument.
"$EMC2_HOME/objects/unit/comptest" < script
echo "load userkins bogus=1" | "$EMC2_HOME/objects/unit/comptest"
