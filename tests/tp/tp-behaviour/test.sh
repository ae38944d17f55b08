#!/bin/bash
# LinuxCNC's planner behaviour (G61/G61.1/G64 corners, overrides, hold, pause, abort, synced I/O, planner type).
exec "$EMC2_HOME/objects/unit/tp_behaviour"
