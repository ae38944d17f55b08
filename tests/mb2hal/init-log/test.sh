#!/bin/bash
# init-log: INIT_DEBUG=3 start-up/shutdown log on stdout and VERSION 1.0 pin names, through halrun.
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cat > "$D/cfg.ini" <<'INI'
[MB2HAL_INIT]
INIT_DEBUG=3
SLOWDOWN=0.5
TOTAL_TRANSACTIONS=3
[TRANSACTION_00]
LINK_TYPE=tcp
TCP_IP=127.0.0.1
TCP_PORT=1
MB_SLAVE_ID=5
MB_TX_CODE=fnct_02_read_discrete_inputs
FIRST_ELEMENT=3
NELEMENTS=2
HAL_TX_NAME=inputs
MAX_UPDATE_RATE=4
DEBUG=0
[TRANSACTION_01]
MB_TX_CODE=fnct_06_write_single_register
FIRST_ELEMENT=100
NELEMENTS=2
HAL_TX_NAME=regs
DEBUG=0
[TRANSACTION_02]
LINK_TYPE=serial
SERIAL_PORT=/dev/openemc-no-such-port
SERIAL_BAUD=9600
SERIAL_PARITY=even
MB_TX_CODE=fnct_03_read_holding_registers
FIRST_ELEMENT=0
NELEMENTS=1
DEBUG=0
INI
printf 'loadusr -W mb2hal config=%s\nshow pin mb2hal.inputs.0\nshow pin mb2hal.regs.0\nshow pin mb2hal.02.0\n' \
    "$D/cfg.ini" > "$D/test.hal"
halrun -f "$D/test.hal" 2> "$D/stderr" | sed -E 's/^(.*unloading HAL module \[)[0-9]+/\1ID/; s/^ +[0-9]+  /   ID  /' \
    | grep -v 'quit_signal DEBUG: signal \[15\] received'
echo "halrun exit ${PIPESTATUS[0]}"
