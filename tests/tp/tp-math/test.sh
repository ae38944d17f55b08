#!/bin/bash
# Planner math: profiles within limits, braking formulas consistent, caps, G2 blends within tolerance.
exec "$EMC2_HOME/objects/unit/tp_math"
