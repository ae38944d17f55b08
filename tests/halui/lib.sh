# lib.sh: start and stop a machine with halui for the halui tests. The machine is
# linuxcncsvr plus nml_responder (a stand-in for task); halui is started the way the
# launcher starts it (halcmd loadusr -Wn halui halui -ini INI).
HALUI_INI="$EMC2_HOME/tests/halui/common/halui.ini"

# start_halui [INI]: realtime, the NML master, the responder, halui; wait for status.
start_halui() {
    local ini="${1:-$HALUI_INI}"
    realtime start || return 1
    SVR_PID=$(linuxcncsvr -ini "$ini" --daemon) || { realtime stop; return 1; }
    "$EMC2_HOME/objects/unit/nml_responder" -ini "$ini" &
    MACHINE_PID=$!
    python3 - <<'PY' || { stop_halui; return 1; }
import sys, time, linuxcnc
s = linuxcnc.stat()
end = time.time() + 20
while time.time() < end:
    s.poll()
    if s.taskbeat > 0:
        sys.exit(0)
    time.sleep(0.02)
sys.stderr.write("machine did not start\n")
sys.exit(1)
PY
    halcmd loadusr -Wn halui halui -ini "$ini" || { stop_halui; return 1; }
}

# stop_halui: halui, the responder and the NML master, then realtime.
stop_halui() {
    halcmd unload halui 2>/dev/null
    [ -n "${MACHINE_PID:-}" ] && kill "$MACHINE_PID" 2>/dev/null && wait "$MACHINE_PID" 2>/dev/null
    if [ -n "${SVR_PID:-}" ]; then
        kill "$SVR_PID" 2>/dev/null
        while kill -0 "$SVR_PID" 2>/dev/null; do sleep 0.02; done
    fi
    MACHINE_PID= SVR_PID=
    realtime stop
}
