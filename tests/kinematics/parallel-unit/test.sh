#!/bin/bash
# Pure math of the delta, tripod, rose and pentapod kinematics: known poses and round trips.
exec "$EMC2_HOME/objects/unit/parallel_unit"
