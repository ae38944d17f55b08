#!/bin/bash
# rotarydeltakins through the fake-HAL harness: geometry pins with defaults, poses both ways, changed geometry, out of reach.
exec "$EMC2_HOME/objects/unit/comptest" < script
