#!/bin/bash
# rotatekins through the fake-HAL harness: pinless, type BOTH, 45 degree XY rotation both ways, unknown module argument refused.
exec "$EMC2_HOME/objects/unit/comptest" < script
