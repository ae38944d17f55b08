#!/bin/bash
# CRLF input (with -U), include "..." relative to the .comp, modparam dummy, userspace .c, .py install.
set -e
tmp=$(mktemp -d)
inst=$EMC2_HOME/bin/hc_tool_probe
trap 'rm -rf "$tmp" "$inst"' EXIT
cp -r crlf.comp sub uprog.c "$tmp/"
cp tool.py "$tmp/hc_tool_probe.py"
cd "$tmp"
halcompile -U --compile crlf.comp
halcompile --compile sub/inc.comp
printf 'load crlf\nfuncts crlf.0\ntrace 1 crlf.0.out\nload inc extra=2\n' > s1
printf 'load inc extra=2\nfuncts inc.0\ntrace 1 inc.0.out\n' > s2
RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest" < s1 | head -3
RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest" < s2
halcompile --compile --userspace uprog.c
./uprog
test -f "$(halcompile --print-modinc)" && echo "modinc exists"
halcompile --install hc_tool_probe.py
stat -c '%a' "$inst"
head -1 "$inst" | grep -c '^#!.*python'
"$inst"
