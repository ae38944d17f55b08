#!/bin/bash
# Pure kinematics helpers: coordinates parsing, identity map, ops-table version check.
exec "$EMC2_HOME/objects/unit/kins_unit"
