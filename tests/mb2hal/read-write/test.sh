#!/bin/bash
# read-write: every function code against modbus-sim: pins follow registers, writes reach the device,
# version 1.1 pin naming (.bit/.bit-inv, .float/.int, writes add .float and .int), PIN_NAMES,
# NELEMENTS > 1 for the single writes (one request per element), and a failing transaction does not stop the others.
. ../lib.sh
sim_start --set hr:0=100 --set hr:1=65535 --set coil:3=1 --set di:2=1 --set ir:5=42 \
    --log "$MB_TMP/writes.log"
{
    printf '[MB2HAL_INIT]\nINIT_DEBUG=0\nVERSION=1.1\nTOTAL_TRANSACTIONS=9\n'
    printf '[TRANSACTION_00]\n'; tcp_link
    printf 'MB_TX_CODE=fnct_03_read_holding_registers\nFIRST_ELEMENT=0\nNELEMENTS=2\nHAL_TX_NAME=hr\n'
    printf 'MB_RESPONSE_TIMEOUT_MS=5000\n'
    printf '[TRANSACTION_01]\nMB_TX_CODE=fnct_01_read_coils\nFIRST_ELEMENT=2\nNELEMENTS=2\n'
    printf '[TRANSACTION_02]\nMB_TX_CODE=fnct_02_read_discrete_inputs\nFIRST_ELEMENT=2\n'
    printf 'PIN_NAMES=door, light\nHAL_TX_NAME=di\n'
    printf '[TRANSACTION_03]\nMB_TX_CODE=fnct_04_read_input_registers\nFIRST_ELEMENT=5\n'
    printf 'PIN_NAMES=temp\nHAL_TX_NAME=ir\n'
    printf '[TRANSACTION_04]\nMB_TX_CODE=fnct_05_write_single_coil\nFIRST_ELEMENT=20\nNELEMENTS=3\n'
    printf 'HAL_TX_NAME=relay\n'
    printf '[TRANSACTION_05]\nMB_TX_CODE=fnct_06_write_single_register\nFIRST_ELEMENT=30\n'
    printf 'PIN_NAMES=speed,accel\nHAL_TX_NAME=vfd\n'
    printf '[TRANSACTION_06]\nMB_TX_CODE=fnct_15_write_multiple_coils\nFIRST_ELEMENT=40\nNELEMENTS=3\n'
    printf 'HAL_TX_NAME=outs\n'
    printf '[TRANSACTION_07]\nMB_TX_CODE=fnct_16_write_multiple_registers\nFIRST_ELEMENT=50\n'
    printf 'NELEMENTS=2\nHAL_TX_NAME=regs\nMAX_UPDATE_RATE=50\n'
    printf '[TRANSACTION_08]\nMB_TX_CODE=fnct_03_read_holding_registers\nFIRST_ELEMENT=998\n'
    printf 'NELEMENTS=4\nHAL_TX_NAME=beyond\nMAX_UPDATE_RATE=100\n'
} > "$MB_TMP/cfg.ini"

halcmd loadusr -W mb2hal config="$MB_TMP/cfg.ini" > "$MB_TMP/load.out" 2>&1 || { cat "$MB_TMP/load.out"; exit 1; }
halcmd show pin mb2hal > "$MB_TMP/pins.txt" 2>&1
awk 'NR > 2 && NF == 5 {print $2, $3, $5}' "$MB_TMP/pins.txt"

wait_until "hr.00 reads 100" pin_is mb2hal.hr.00.int 100
wait_until "hr.01 reads 65535" pin_is mb2hal.hr.01.int 65535
wait_until "hr.01.float reads 65535" pin_is mb2hal.hr.01.float 65535
wait_until "coil 3 is TRUE" pin_is mb2hal.01.01.bit TRUE
pin_is mb2hal.01.01.bit-inv FALSE && echo "coil 3 inverted is FALSE"
pin_is mb2hal.01.00.bit FALSE && echo "coil 2 is FALSE"
pin_is mb2hal.01.00.bit-inv TRUE && echo "coil 2 inverted is TRUE"
wait_until "di door is TRUE" pin_is mb2hal.di.door.bit TRUE
wait_until "ir temp reads 42" pin_is mb2hal.ir.temp.int 42

sim_set hr 1 7
sim_set ir 5 1000
sim_set coil 2 1
wait_until "hr.01 follows to 7" pin_is mb2hal.hr.01.int 7
wait_until "ir temp follows to 1000" pin_is mb2hal.ir.temp.float 1000
wait_until "coil 2 follows to TRUE" pin_is mb2hal.01.00.bit TRUE
wait_until "coil 2 inverted follows to FALSE" pin_is mb2hal.01.00.bit-inv FALSE

halcmd setp mb2hal.relay.00.bit 1
halcmd setp mb2hal.relay.02.bit 1
halcmd setp mb2hal.vfd.speed.float 1499.6
halcmd setp mb2hal.vfd.accel.float 100.4
halcmd setp mb2hal.vfd.accel.int 20
halcmd setp mb2hal.outs.02.bit 1
halcmd setp mb2hal.regs.00.float -1
halcmd setp mb2hal.regs.01.float 70000
wait_until "fnct_05 wrote coil 20" logged "write coil 20 1"
wait_until "fnct_05 wrote coil 22 (third element)" logged "write coil 22 1"
wait_until "fnct_06 wrote rounded 1500" logged "write hr 30 1500"
wait_until "fnct_06 wrote float + int 120 to the second register" logged "write hr 31 120"
wait_until "fnct_15 wrote coil 42" logged "write coil 42 1"
wait_until "fnct_16 wrote -1 as 65535" logged "write hr 50 65535"
wait_until "fnct_16 clamped 70000" logged "write hr 51 65535"

wait_until "reading past the table counts errors" pin_above mb2hal.beyond.num_errors 2
sim_set hr 0 5
wait_until "others keep running beside it" pin_is mb2hal.hr.00.int 5
for p in hr 01 di ir relay vfd outs regs; do
    echo "$p.num_errors=$(halcmd getp mb2hal.$p.num_errors)"
done

halcmd unload mb2hal
halcmd waitusr mb2hal
echo "left: [$(halcmd list comp mb2hal)]"
