#!/bin/bash
# genhexkins through the fake-HAL harness; a second run checks a bad coordinates= argument.
"$EMC2_HOME/objects/unit/comptest" < script
echo "load genhexkins coordinates=xyzq" | "$EMC2_HOME/objects/unit/comptest"
