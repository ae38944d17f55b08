#!/bin/bash
# limit3 follower: limits never violated, exact lock-on, no overshoot at min/max.
exec "$EMC2_HOME/objects/unit/limit3_unit"
