#!/bin/bash
# Pure math of corexykins, rotatekins, matrixkins and scorbot-kins: known poses and round trips.
exec "$EMC2_HOME/objects/unit/cartesian_unit"
