#!/bin/bash
# halrun command line: usage errors, extensions, exit status of a failing file, cleanup.
cd "$(dirname "$0")"
run() { echo "> halrun $*"; halrun "$@" 2>&1 | grep -v "^Note: "; echo "exit ${PIPESTATUS[0]}"; }
run a.hal b.hal
run -f x.hal y.hal
run -Z
run notes.txt
run ok.hal
run fail.hal
run missing.hal
run -k fail.hal
run noini.ini
echo "> realtime still running?"
realtime status > /dev/null 2>&1 && echo yes || echo no
