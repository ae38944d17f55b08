#!/bin/bash
# OWORD_WARNONLY=1: flow errors are printed on stderr and the program goes on; other errors still stop it.
rs274 -g -i test.ini test.ngc 2>&1 | awk '{$1=""; print}'
echo "exit ${PIPESTATUS[0]}"
echo "== without the INI"
rs274 -g test.ngc 2>&1 >/dev/null | tail -n 2
