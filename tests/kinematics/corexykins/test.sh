#!/bin/bash
# corexykins through the fake-HAL harness: pinless, type BOTH, CoreXY formulas both ways, unknown module argument refused.
exec "$EMC2_HOME/objects/unit/comptest" < script
