#!/bin/bash
# setp/getp/ptype on pins and params of every type: writability, value syntax, error texts.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL'
loadrt sum2
loadrt toggle
loadrt conv_s32_u32
loadrt conv_u64_s64
loadrt conv_s64_u64
setp sum2.0.in0 1.5
getp sum2.0.in0
sum2.0.in1 = -2e-3
getp sum2.0.in1
ptype sum2.0.in1
setp sum2.0.out 1
setp sum2.0.in0 1e999
setp sum2.0.in0 12abc
setp sum2.0.gain0 123456789
getp sum2.0.gain0
ptype sum2.0.gain0
setp toggle.0.debounce 0x10
getp toggle.0.debounce
ptype toggle.0.debounce
setp toggle.0.debounce -1
setp toggle.0.debounce 4294967296
setp toggle.0.in yes
getp toggle.0.in
setp toggle.0.in 2
setp toggle.0.out ON
getp toggle.0.out
ptype toggle.0.out
setp conv-s32-u32.0.in 017
getp conv-s32-u32.0.in
ptype conv-s32-u32.0.in
setp conv-s32-u32.0.in 0x80000000
setp conv-s32-u32.0.in 5x
setp conv-u64-s64.0.in -1
getp conv-u64-s64.0.in
setp conv-s64-u64.0.in -9223372036854775808
getp conv-s64-u64.0.in
setp sum2.0.tmax 7
getp sum2.0.tmax
setp sum2.0.tmax-increased 1
getp sum2.0.tmax-increased
ptype sum2.0.tmax-increased
setp nosuch 1
getp nosuch
ptype nosuch
setp sum2.0.in0 => 1
newsig s float
net s sum2.0.in1
setp sum2.0.in1 3
getp sum2.0.in1
HAL
echo "exit $?"
realtime stop
