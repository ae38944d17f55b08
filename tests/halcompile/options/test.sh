#!/bin/bash
# Options: singleton, count_function, default_count with a hal_ name, period no, -P personalities.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
here=$PWD
cp *.comp "$tmp/"
cd "$tmp"
halcompile --compile single.comp cf.comp hal_dc.comp
halcompile -P 2 --compile pp.comp
halcompile --personalities=2 pp.comp
grep -c 'static int personality\[2\]' pp.c
run() { echo "== $*"; printf '%b' "$*" | RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest"; }
run 'load single\nshow\nfuncts single\ntrace 2 single.calls\n'
run 'load single count=2\n'
run 'load cf\nfuncts cf.0 cf.1\ntrace 1 cf.0.index cf.1.index\n'
run 'load cf names=a,b\nshow\n'
run 'load cf names=a\n'
run 'load cf names=a,,b\n'
run 'load hal_dc\nshow\n'
run 'load pp count=3 personality=5,7\nfuncts pp.0 pp.1 pp.2\ntrace 1 pp.0.p pp.1.p pp.2.p\nshow\n'
