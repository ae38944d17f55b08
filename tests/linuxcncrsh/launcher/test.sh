#!/bin/bash
# A whole machine through the launcher with linuxcncrsh as its display ([DISPLAY]DISPLAY
# with options) and halui: a TCP session turns it on, homes and moves it, halui's pins
# show it and run an MDI command, and 'shutdown' ends the launcher with status 0.
export LC_ALL=C
PORT=$((21000 + ${OPENEMC_INSTANCE:-0}))
export RSH_PORT=$PORT
sed "s/@PORT@/$PORT/" machine.ini.in > machine.ini
linuxcnc -r machine.ini > launcher.log 2>&1 &
LAUNCHER=$!
CLIENT="$EMC2_HOME/tests/linuxcncrsh/common/rshclient.py"
python3 "$CLIENT" wait-port "$PORT" || { kill $LAUNCHER; wait $LAUNCHER; exit 1; }
PYTHONPATH="$EMC2_HOME/tests/linuxcncrsh/common:$PYTHONPATH" python3 -u - <<'PY'
import subprocess
import sys
import time
from rshclient import Session, TIMEOUT_S


def pin(name):
    return subprocess.run(["halcmd", "getp", name], capture_output=True, text=True).stdout.strip()


def until(s, req, reply):
    end = time.time() + TIMEOUT_S
    while time.time() < end:
        got = s.ask(req)
        if got == [reply]:
            print("> %s (until)\n  %s" % (req, reply))
            return
        time.sleep(0.02)
    print("FAIL: %s: %s" % (req, got))
    sys.exit(1)


s = Session()
for req in ("hello EMC launcher-test 1.1", "set verbose on", "set enable EMCTOO", "set wait_mode done",
            "set estop off", "set machine on", "get machine", "set mode manual", "set home -1",
            "set joint_wait_homed", "get joint_homed"):
    s.show(req)
print("halui.machine.is-on", pin("halui.machine.is-on"), "halui.joint.2.is-homed", pin("halui.joint.2.is-homed"))
for req in ("set mode mdi", "set mdi G0 X1 Y2", "get abs_cmd_pos", "get program_status"):
    s.show(req)
print("halui.axis.x.pos-commanded", pin("halui.axis.x.pos-commanded"))
print("== halui.mdi-command-00 (G0 X0 Y0) from MDI mode")
subprocess.run(["halcmd", "setp", "halui.mdi-command-00", "1"], check=True)
until(s, "get abs_cmd_pos x", "ABS_CMD_POS X 0.000000")
subprocess.run(["halcmd", "setp", "halui.mdi-command-00", "0"], check=True)
until(s, "get abs_cmd_pos y", "ABS_CMD_POS Y 0.000000")
s.show("get mode")
s.send("shutdown")
print("closed after shutdown:", s.closed())
PY
rc=$?
wait $LAUNCHER
echo "launcher exit $?"
grep -i "error" launcher.log
rm -f machine.ini launcher.log
exit $rc
