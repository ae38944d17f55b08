#!/bin/bash
# clarke2, clarke3, clarkeinv: the transforms in the fake-HAL harness, one module per run.
run() { "$EMC2_HOME/objects/unit/comptest" | grep -v '^hal_init\|^rtapi_app_main'; }
echo "== clarke2: a=1 b=-0.5"
run < script
echo "== clarke3: a=1 b=-0.5 c=-0.5, then all 1 (only h)"
run <<'S'
load clarke3
functs clarke3.0
set clarke3.0.a 1
set clarke3.0.b -0.5
set clarke3.0.c -0.5
trace 1 clarke3.0.x clarke3.0.y clarke3.0.h
set clarke3.0.a 1
set clarke3.0.b 1
set clarke3.0.c 1
trace 1 clarke3.0.x clarke3.0.y clarke3.0.h
S
echo "== clarkeinv: x=1 back to a balanced set; theta 0.25 rotates x onto y"
run <<'S'
load clarkeinv
functs clarkeinv.0
set clarkeinv.0.x 1
trace 1 clarkeinv.0.a clarkeinv.0.b clarkeinv.0.c
set clarkeinv.0.theta 0.25
trace 1 clarkeinv.0.a clarkeinv.0.b clarkeinv.0.c
S
