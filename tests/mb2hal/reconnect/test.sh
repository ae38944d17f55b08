#!/bin/bash
# reconnect: num_errors counts while the device is gone, mb2hal reconnects when it is back,
# a dead link does not block a live one, and SIGTERM ends mb2hal cleanly (exit 0, component gone).
. ../lib.sh
sim_start --set hr:0=11
{
    printf '[MB2HAL_INIT]\nINIT_DEBUG=1\nTOTAL_TRANSACTIONS=2\n'
    printf '[TRANSACTION_00]\n'; tcp_link
    printf 'MB_TX_CODE=fnct_03_read_holding_registers\nFIRST_ELEMENT=0\nNELEMENTS=1\nHAL_TX_NAME=live\n'
    printf 'MB_RESPONSE_TIMEOUT_MS=5000\n'
    printf '[TRANSACTION_01]\nTCP_PORT=1\nMB_TX_CODE=fnct_02_read_discrete_inputs\nFIRST_ELEMENT=0\nNELEMENTS=1\n'
    printf 'HAL_TX_NAME=dead\n'
} > "$MB_TMP/cfg.ini"

mb2hal config="$MB_TMP/cfg.ini" 2> "$MB_TMP/mb2hal.err" &
MB_PID=$!
wait_until "live reads 11" pin_is mb2hal.live.00.int 11
wait_until "dead link counts errors" pin_above mb2hal.dead.num_errors 1

sim_stop
wait_until "device gone counts errors" pin_above mb2hal.live.num_errors 1
sim_start --set hr:0=22
wait_until "reconnected, live reads 22" pin_is mb2hal.live.00.int 22
sim_set hr 0 33
wait_until "live follows to 33" pin_is mb2hal.live.00.int 33

grep -q '^mb2hal: \[TRANSACTION_01\] cannot connect to 127.0.0.1:1: ' "$MB_TMP/mb2hal.err" &&
    echo "connect failure reported"
kill -TERM $MB_PID
wait $MB_PID
echo "mb2hal exit status $?"
echo "left: [$(halcmd list comp mb2hal)]"
