#!/bin/bash
# Serial-arm kinematics math: known poses, DH-chain agreement, round trips, refused poses.
exec "$EMC2_HOME/objects/unit/serial_unit"
