#!/bin/bash
# rosekins through the fake-HAL harness: revolution pins, polar map both ways, the rotary joint continuing past 180 degrees.
exec "$EMC2_HOME/objects/unit/comptest" < script
