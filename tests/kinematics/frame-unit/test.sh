#!/bin/bash
# Non-switchable kinematics frame: check before hal_init, setup errors, flags, type, ops table.
exec "$EMC2_HOME/objects/unit/kins_frame_unit"
