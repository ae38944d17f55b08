#!/bin/bash
# config-errors: bin/mb2hal exits 1 with a clear message on bad arguments, bad configs and a taken name.
. ../lib.sh
cd "$MB_TMP" || exit 1
# run ARGS...: runs mb2hal and prints its messages and exit status.
run() {
    echo "\$ mb2hal $*"
    mb2hal "$@" 2>&1
    echo "exit $?"
}
printf '[MB2HAL_INIT]\nTOTAL_TRANSACTIONS=1\n[TRANSACTION_00]\nLINK_TYPE=tcp\nTCP_IP=127.0.0.1\n' > bad.ini
printf 'MB_SLAVE_ID=1\nMB_TX_CODE=fnct_03_read_holding_registers\nFIRST_ELEMENT=0\nNELEMENTS=200\n' >> bad.ini
printf '[MB2HAL_INIT]\nINIT_DEBUG=0\nTOTAL_TRANSACTIONS=1\n[TRANSACTION_00]\nLINK_TYPE=tcp\n' > dead.ini
printf 'TCP_IP=127.0.0.1\nTCP_PORT=1\nMB_SLAVE_ID=1\nMB_TX_CODE=fnct_02_read_discrete_inputs\nFIRST_ELEMENT=0\nNELEMENTS=1\n' >> dead.ini
run
run config=
run cfg.ini
run config=nosuch.ini
run config=bad.ini
halcmd loadusr -W mb2hal config=dead.ini > load.out 2>&1 || cat load.out
run config=dead.ini
halcmd unload mb2hal
halcmd waitusr mb2hal
echo "left: [$(halcmd list comp mb2hal)]"
