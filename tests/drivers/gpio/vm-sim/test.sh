#!/bin/bash
# vm-sim: hal_gpio against two gpio-sim chips inside the VM: pin names, inputs following the
# simulated pulls, outputs reaching the lines (invert, inactive level at load, open drain and
# bias applied at request), the reset function, lines split across chips, a busy line, release.
. "$EMC2_HOME/tests/drivers/vm-lib.sh"
vm_run -- bash ./inner.sh
echo "vm status $?"
