#!/bin/bash
# Random move chains with random limits: every servo sample within velocity/acceleration/jerk limits,
# every end point exact, every chain finishes; the cycles that found no safe continuation (and braked
# within the limits) are counted against the expected figure.
# (make fuzz runs the long sweep of 100000 chains.)
exec "$EMC2_HOME/objects/unit/tp_random" 2000
