#!/bin/bash
# config-parser: the mb2hal config parser on good and bad files (defaults, inheritance, every error path),
# VERSION 1.1-only codes, NELEMENTS > 1 for the single writes, and the INIT_DEBUG=3 log of a good file.
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cd "$D" || exit 1
TCP='LINK_TYPE=tcp
TCP_IP=10.0.0.2
MB_SLAVE_ID=3'
# mk NAME: writes stdin to NAME.ini.
mk() { cat > "$1.ini"; }
# tx NN CODE FIRST N: a minimal transaction section without link keys.
tx() { printf '[TRANSACTION_%s]\nMB_TX_CODE=%s\nFIRST_ELEMENT=%s\nNELEMENTS=%s\n' "$@"; }
init() { printf '[MB2HAL_INIT]\nTOTAL_TRANSACTIONS=%s\n' "$1"; }

mk good <<EOF2
# comment line
; another comment
[MB2HAL_INIT]
INIT_DEBUG = 3
VERSION=1.1
HAL_MODULE_NAME=vfd
SLOWDOWN=0.25
TOTAL_TRANSACTIONS=4

[TRANSACTION_00]
$TCP
TCP_PORT=1502
MB_TX_CODE=fnct_03_read_holding_registers
FIRST_ELEMENT=1
PIN_NAMES=speed , load,temp
MB_RESPONSE_TIMEOUT_MS=100
[TRANSACTION_01]
MB_TX_CODE=fnct_15_write_multiple_coils
FIRST_ELEMENT=65535
NELEMENTS=1
HAL_TX_NAME=coils
MAX_UPDATE_RATE=2.5
DEBUG=0
[TRANSACTION_02]
LINK_TYPE=serial
SERIAL_PORT=/dev/ttyUSB0
SERIAL_BAUD=19200
SERIAL_PARITY=even
SERIAL_STOP=2
SERIAL_DELAY_MS=10
MB_SLAVE_ID=7
MB_TX_CODE=fnct_06_write_single_register
FIRST_ELEMENT=8
NELEMENTS=1
[TRANSACTION_03]
MB_TX_CODE=FNCT_02_READ_DISCRETE_INPUTS
FIRST_ELEMENT=0
NELEMENTS=2000
MB_BYTE_TIMEOUT_MS=20
EOF2
{ init 1; tx 00 fnct_02_read_discrete_inputs 0 8; echo "$TCP"; echo "MB_TX_COD=x"; echo "[EXTRA]"; echo "A=1"; } | mk unknown-key
printf '[OTHER]\nA=1\n' | mk no-init
printf '[MB2HAL_INIT]\nINIT_DEBUG=1\n' | mk no-total
{ printf '[MB2HAL_INIT]\nTOTAL_TRANSACTIONS=abc\n'; } | mk total-text
{ printf '[MB2HAL_INIT]\nTOTAL_TRANSACTIONS=0\n'; } | mk total-zero
{ init 2; tx 00 fnct_02_read_discrete_inputs 0 8; echo "$TCP"; } | mk missing-section
{ init 1; tx 00 fnct_02_read_discrete_inputs 0 8; } | mk no-link
{ init 1; tx 00 fnct_02_read_discrete_inputs 0 8; printf 'LINK_TYPE=udp\nMB_SLAVE_ID=1\n'; } | mk link-udp
{ init 1; tx 00 fnct_02_read_discrete_inputs 0 8; printf 'LINK_TYPE=tcp\nMB_SLAVE_ID=256\n'; } | mk no-ip
{ init 1; tx 00 fnct_02_read_discrete_inputs 0 8; printf 'LINK_TYPE=serial\nMB_SLAVE_ID=1\nSERIAL_PARITY=mark\nSERIAL_STOP=3\n'; } | mk serial-bad
{ init 1; printf '[TRANSACTION_00]\nFIRST_ELEMENT=0\nNELEMENTS=1\nMB_TX_CODE=fnct_07_read_status\n'; echo "$TCP"; } | mk bad-code
{ init 1; printf '[TRANSACTION_00]\nNELEMENTS=1\n'; echo "$TCP"; } | mk no-code-first
{ init 3; tx 00 fnct_03_read_holding_registers 0 126; echo "$TCP"; tx 01 fnct_15_write_multiple_coils 0 1969; tx 02 fnct_16_write_multiple_registers 0 0; } | mk nelements
{ init 1; tx 00 fnct_02_read_discrete_inputs 65535 2; echo "$TCP"; } | mk past-end
{ init 1; printf '[TRANSACTION_00]\nMB_TX_CODE=fnct_02_read_discrete_inputs\nFIRST_ELEMENT=0\nPIN_NAMES=a\n'; echo "$TCP"; } | mk names-v10
{ printf '[MB2HAL_INIT]\nVERSION=1.1\nTOTAL_TRANSACTIONS=4\n'
  names() { printf '[TRANSACTION_0%s]\nMB_TX_CODE=fnct_01_read_coils\nFIRST_ELEMENT=0\nPIN_NAMES=%s\n' "$@"; }
  names 0 a,b,a; echo "$TCP"; names 1 'a,,b'; names 2 'a b'; names 3 x; echo NELEMENTS=1; } | mk names-bad
{ printf '[MB2HAL_INIT]\nVERSION=1.1\nTOTAL_TRANSACTIONS=1\n'; tx 00 fnct_01_read_coils 0 1 | sed '/NELEMENTS/d'; echo "$TCP"; } | mk no-elements-v11
{ init 3; tx 00 fnct_02_read_discrete_inputs 0 1; echo "$TCP"; echo HAL_TX_NAME=x; tx 01 fnct_02_read_discrete_inputs 0 1; echo HAL_TX_NAME=x
  tx 02 fnct_02_read_discrete_inputs 0 1; echo HAL_TX_NAME=a_very_long_transaction_name_for_hal; } | mk tx-names
{ printf '[MB2HAL_INIT]\nVERSION=2.0\nSLOWDOWN=abc\nINIT_DEBUG=9\nHAL_MODULE_NAME=my mod\nTOTAL_TRANSACTIONS=1\n'
  tx 00 fnct_02_read_discrete_inputs x 1; echo "$TCP"; printf 'MAX_UPDATE_RATE=-1\nTCP_PORT=70000\n'; } | mk many-errors
{ init 2; tx 00 fnct_01_read_coils 0 1; echo "$TCP"; tx 01 fnct_05_write_single_coil 0 1; } | mk v10-codes
{ printf '[MB2HAL_INIT]\nVERSION=1.1\nTOTAL_TRANSACTIONS=2\n'; tx 00 fnct_05_write_single_coil 4 4; echo "$TCP"
  tx 01 fnct_06_write_single_register 10 3; } | mk v11-singles
printf '[MB2HAL_INIT]\nTOTAL_TRANSACTIONS\n' | mk no-equals
printf 'TOTAL_TRANSACTIONS=1\n' | mk outside
printf '[MB2HAL_INIT\n' | mk bad-header

"$EMC2_HOME/objects/unit/mb2hal_config" good.ini unknown-key.ini no-init.ini no-total.ini total-text.ini \
    total-zero.ini missing-section.ini no-link.ini link-udp.ini no-ip.ini serial-bad.ini bad-code.ini \
    no-code-first.ini nelements.ini past-end.ini names-v10.ini names-bad.ini no-elements-v11.ini \
    tx-names.ini many-errors.ini v10-codes.ini v11-singles.ini no-equals.ini outside.ini bad-header.ini missing.ini 2>&1
