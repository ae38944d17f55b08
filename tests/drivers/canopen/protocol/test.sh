#!/bin/bash
# protocol: the cia402 driver's engine against the simulated CiA 402 drive over an in-memory bus
# with simulated time: set-up writes, absent node, enable, motion, EMCY, heartbeat loss, reboot,
# pre-operational, feedback loss, malformed frames, enable timeout, bad command, refused set-up,
# the 32-bit position wrap; every fault reported once and recovered by a reset.
exec "$EMC2_HOME/objects/unit/cia402_loop"
