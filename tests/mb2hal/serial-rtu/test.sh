#!/bin/bash
# serial-rtu: mb2hal over a Modbus RTU link (modbus-sim on a pty): reads, writes, inherited serial settings.
. ../lib.sh
sim_start --rtu 5 --set hr:3=321 --set di:0=1 --log "$MB_TMP/writes.log"
{
    printf '[MB2HAL_INIT]\nINIT_DEBUG=0\nHAL_MODULE_NAME=rtu\nTOTAL_TRANSACTIONS=3\n'
    printf '[TRANSACTION_00]\nLINK_TYPE=serial\nSERIAL_PORT=%s\nSERIAL_BAUD=115200\n' "$SIM_PTY"
    printf 'SERIAL_BITS=8\nSERIAL_PARITY=none\nSERIAL_STOP=1\nSERIAL_DELAY_MS=2\nMB_SLAVE_ID=5\n'
    printf 'MB_RESPONSE_TIMEOUT_MS=5000\nMB_TX_CODE=fnct_03_read_holding_registers\n'
    printf 'FIRST_ELEMENT=3\nNELEMENTS=1\nHAL_TX_NAME=hr\n'
    printf '[TRANSACTION_01]\nMB_TX_CODE=fnct_02_read_discrete_inputs\nFIRST_ELEMENT=0\nNELEMENTS=1\n'
    printf '[TRANSACTION_02]\nMB_TX_CODE=fnct_06_write_single_register\nFIRST_ELEMENT=9\nNELEMENTS=1\n'
    printf 'HAL_TX_NAME=vfd\nMAX_UPDATE_RATE=20\n'
} > "$MB_TMP/cfg.ini"

halcmd loadusr -Wn rtu mb2hal config="$MB_TMP/cfg.ini" > "$MB_TMP/load.out" 2>&1 || { cat "$MB_TMP/load.out"; exit 1; }
wait_until "hr reads 321 over RTU" pin_is rtu.hr.00.int 321
wait_until "inherited link reads di 0" pin_is rtu.01.00 TRUE
sim_set hr 3 4000
wait_until "hr follows to 4000" pin_is rtu.hr.00.float 4000
halcmd setp rtu.vfd.00 1234
wait_until "fnct_06 over RTU wrote 1234" logged "write hr 9 1234"
for p in hr 01 vfd; do
    echo "$p.num_errors=$(halcmd getp rtu.$p.num_errors)"
done
halcmd unload rtu
halcmd waitusr rtu
echo "left: [$(halcmd list comp rtu)]"
