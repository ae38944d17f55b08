#!/bin/bash
# Where linuxcncrsh listens: loopback by default; another address only with both passwords
# changed from LinuxCNC's defaults; a port in use and bad options are reported with exit 1.
. "$EMC2_HOME/tests/linuxcncrsh/lib.sh"
export LC_ALL=C
start_machine || exit 1
PY="python3 $EMC2_HOME/tests/linuxcncrsh/common/rshclient.py"
run() {
    echo "== linuxcncrsh $*"
    linuxcncrsh -p "$RSH_PORT" "$@" -- -ini "$RSH_INI" 2>&1 | sed "s/$RSH_PORT/PORT/g"
    echo "exit ${PIPESTATUS[0]}"
}
run --bind 0.0.0.0
run --bind 0.0.0.0 --connectpw secret
run -b 0.0.0.0 -w secret -e EMCTOO
run --bind no.such.host.invalid
run --port 0
run --sessions many
run --frobnicate
echo "== linuxcncrsh -p PORT --name"
linuxcncrsh -p "$RSH_PORT" --name 2>&1 | head -1
echo "== linuxcncrsh --help"
linuxcncrsh --help | head -1
echo "== any address with own passwords: listens; the passwords are the new ones"
start_rsh --bind 0.0.0.0 --connectpw secret --enablepw secret2 || exit 1
PYTHONPATH="$EMC2_HOME/tests/linuxcncrsh/common" python3 - <<'PY'
from rshclient import Session
s = Session()
for req in ("hello EMC me", "hello secret me", "set echo off", "set enable EMCTOO", "set enable secret2",
            "get enable"):
    s.show(req)
PY
echo "== a second server on the same port"
run
stop_rsh
echo "== localhost and ::1 are loopback"
start_rsh --bind localhost || exit 1
$PY wait-port "$RSH_PORT" && echo "listening on localhost"
stop_rsh
stop_machine
rm -f rsh.log
