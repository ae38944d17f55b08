#!/bin/bash
# Non-random tool changer: T/M6 handshakes on iocontrol.0, T0, M61, G10 L1, tool_offset();
# the saved table after a mix of G10 L1, M6 and M61 keeps every tool with its own number.
. ../lib/run-machine.sh
run_machine || exit 1
echo "saved table:"
grep -v '^;' tool.tbl
