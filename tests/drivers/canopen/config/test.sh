#!/bin/bash
# config: the cia402 configuration reader: a machine INI with drive sections (defaults, overrides,
# SDO lines, the set-up steps built from it, period values for 1 ms and 250 us), then every kind of
# mistake, each reported with file and line.
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
cd "$D" || exit 1
dump() {
    echo "== $1 ${2:-}"
    "$EMC2_HOME/objects/unit/cia402_config_dump" "$@"
    echo "status $?"
}
cat > good.ini <<'INI'
[EMC]
MACHINE = cia402 test   ; other sections of a machine INI are left alone
[CIA402]
INTERFACE = can0
HEARTBEAT_MS = 50
SYNC_COB_ID = 0x081
[CIA402_DRIVE_0]
NODE_ID = 1
POSITION_SCALE = 10000   # counts per mm
SDO = 6081:00 u32 500000
SDO = 0x2000:0x01 i16 -12
SDO = 2000:02 u8 0xFF
[CIA402_DRIVE_1]
NODE_ID = 0x7f
INTERFACE = can1
POSITION_SCALE = -1.5
HEARTBEAT_TIMEOUT_MS = 1000
VELOCITY_FEEDBACK = 0
SYNC_PERIOD_OBJECTS = 0
SDO = 60C2:01 u8 1
INI
dump good.ini
dump good.ini 250000
printf '[CIA402_DRIVE_0]\nNODE_ID=3\nINTERFACE=vcan0\n' > minimal.ini
dump minimal.ini
dump nosuch.ini
printf '[EMC]\nX=1\n' > empty.ini
dump empty.ini
cat > bad.ini <<'INI'
[CIA402]
INTERFACE = can0
NODE_ID = 3
HEARTBEAT_MS = 0
[CIA402_DRIVE_0]
NODE_ID = 128
NODE_ID = 1
POSITION_SCALE = 0
POSITION_SCALE = abc
this line has no equals sign
[CIA402_DRIVE_1]
NODE_ID = 2
FOO = 1
INTERFACE = a/b
SDO = 6081:00 u32
SDO = 6081 u32 5
SDO = 6081:00 u64 5
SDO = 6081:00 u8 256
SDO = 1600:01 u32 0
SDO = 6040:00 u16 6
SDO = 1017:00 u16 10
SDO = 1006:00 u32 1000
SDO = 2000:01 i8 -129
HEARTBEAT_MS = 100
HEARTBEAT_TIMEOUT_MS = 50
VELOCITY_FEEDBACK = 2
SYNC_COB_ID = 0x80
[CIA402_DRIVE_3]
NODE_ID = 1
[CIA402_DRIVE_x]
[CIA402_DRIVE_01]
[broken
INI
dump bad.ini
cat > clash.ini <<'INI'
[CIA402]
INTERFACE = can0
[CIA402_DRIVE_0]
NODE_ID = 4
[CIA402_DRIVE_1]
NODE_ID = 4
[CIA402_DRIVE_2]
NODE_ID = 4
INTERFACE = can1
[CIA402_DRIVE_3]
[CIA402_DRIVE_0]
INI
dump clash.ini
printf '[CIA402_DRIVE_0]\nNODE_ID=1\n' > noif.ini
dump noif.ini
