#!/bin/bash
# cia402 benchmark: the protocol engine per servo cycle for 1, 8 and 32 drives (no socket I/O),
# then, where the VM is available, cia402.read and cia402.write per cycle through HAL with their
# socket calls, two cia402-sim drives on vcan0 (p50, p99, max; under TCG emulation).
[ -n "${BASH_VERSION:-}" ] || exec bash "$0" "$@"
top=$(cd "$(dirname "$0")/../../.." && pwd)
. "$top/scripts/rip-environment" >/dev/null 2>&1
export OPENEMC_INSTANCE=${OPENEMC_INSTANCE:-201}
export EMC2_HOME=$top
"$top/objects/unit/cia402_bench" || exit 1
. "$top/tests/drivers/vm-lib.sh"
if reason=$(vm_unusable); then
    echo "cia402: socket benchmark skipped: $reason"
    exit 0
fi
cd "$(dirname "$0")" && vm_run -- bash ./vm-bench.sh
