#!/bin/bash
# demux_generic: config errors (size 2000 caps at 1024), pins of each type and size, routing by sel-int and sel-bits.
for args in "" "config=bx4" "config=bf0" "config=b1" "config=bf2000"; do
    echo "== $args"
    echo "load demux_generic $args" | "$EMC2_HOME/objects/unit/comptest"
done
echo "== config=fs4,bf3"
"$EMC2_HOME/objects/unit/comptest" <<'SCRIPT'
load demux_generic config=fs4,bf3
show
functs demux-gen.00 demux-gen.01
set demux-gen.00.in-float -2.7
cycle
get demux-gen.00.out-s32-00 demux-gen.00.out-s32-01 demux-gen.00.out-s32-02 demux-gen.00.out-s32-03
set demux-gen.00.sel-bit-01 1
cycle
get demux-gen.00.out-s32-00 demux-gen.00.out-s32-01 demux-gen.00.out-s32-02 demux-gen.00.out-s32-03
set demux-gen.00.sel-int 1
cycle
get demux-gen.00.out-s32-00 demux-gen.00.out-s32-01 demux-gen.00.out-s32-02 demux-gen.00.out-s32-03
set demux-gen.00.sel-int 9
cycle
get demux-gen.00.out-s32-00 demux-gen.00.out-s32-01 demux-gen.00.out-s32-02 demux-gen.00.out-s32-03
set demux-gen.01.in-bit 1
set demux-gen.01.sel-int 2
cycle
get demux-gen.01.out-float-00 demux-gen.01.out-float-01 demux-gen.01.out-float-02
SCRIPT
