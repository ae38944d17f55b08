#!/bin/bash
# 5/6-axis kinematics math: hand-computed poses, refusals, joint mapping, round trips over grids.
exec "$EMC2_HOME/objects/unit/fiveaxis_unit"
