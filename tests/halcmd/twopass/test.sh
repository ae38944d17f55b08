#!/bin/bash
# halrun with a TWOPASS INI file: merged loadrt, loadusr in pass 0, #NOTWOPASS, errors.
cd "$(dirname "$0")"
run() { echo "> halrun $*"; halrun "$@" 2>&1 | grep -v '^Note: '; echo "exit ${PIPESTATUS[0]}"; }
run twopass.ini
run mix.ini
run bad.ini
