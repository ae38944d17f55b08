#!/bin/bash
# lineardeltakins through the fake-HAL harness: L and R pins with defaults, centred and offset poses, changed geometry, out of reach.
exec "$EMC2_HOME/objects/unit/comptest" < script
