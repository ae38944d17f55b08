#!/bin/bash
# newsig/delsig/sets/gets/stype: every type word, value syntax, ports and error texts.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL'
newsig b bit
newsig f FLOAT
newsig s s32
newsig u u32
newsig ls s64
newsig lu u64
newsig p port
newsig r real
newsig bb Bool
newsig si sint
newsig ui uint
newsig x signed
newsig y blah
newsig b bit
newsig toolong
stype b
stype f
stype s
stype u
stype ls
stype lu
stype p
stype r
stype bb
stype si
stype ui
stype nope
gets b
sets b yes
gets b
sets b Off
gets b
sets b 2
sets f 1e-3
gets f
sets f 123456789
gets f
sets f 1e999
sets f 12abc
sets f "3 x"
gets f
sets s 017
gets s
sets s 0x80000000
sets s -2147483648
gets s
sets u 4294967295
gets u
sets u -1
sets lu -1
gets lu
sets ls -9223372036854775808
gets ls
gets p
sets p 100
gets p
sets p 100
sets nope 1
gets nope
delsig nope
delsig b
gets b
list sig
delsig all
list sig
delsig all
HAL
echo "exit $?"
realtime stop
