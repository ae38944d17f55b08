#!/bin/bash
# vm-vcan: cia402 through real HAL against cia402-sim on a vcan interface inside the VM: pins,
# set-up and CAN frames both ways (candump), enable and motion, EMCY, heartbeat loss, a reboot,
# malformed frames, each fault reported once with outputs disabled and recovered by a reset, and a
# refused set-up write naming its configuration line.
. "$EMC2_HOME/tests/drivers/vm-lib.sh"
vm_run -- bash ./inner.sh
echo "vm status $?"
