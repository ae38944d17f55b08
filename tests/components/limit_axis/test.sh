#!/bin/bash
# Drive limit_axis with the fake-HAL harness (three ranges), then show that personality 0 makes two ranges.
"$EMC2_HOME/objects/unit/comptest" < script
echo "== personality 0"
printf 'load limit_axis\nshow\n' | "$EMC2_HOME/objects/unit/comptest"
