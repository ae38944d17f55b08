# lib.sh: start and stop a machine with halui for the halui tests. By default the machine
# is linuxcncsvr plus nml_responder (a stand-in for task) and halui is started the way the
# launcher starts it (halcmd loadusr -Wn halui halui -ini INI). With OPENEMC_TEST_MACHINE
# set to a command that runs a configuration in the foreground (e.g. "linuxcnc -r"), that
# command runs the INI instead and starts halui itself ([HAL]HALUI).
HALUI_INI="$EMC2_HOME/tests/halui/common/halui.ini"

# start_halui [INI]: everything up; returns once task publishes status and halui runs.
start_halui() {
    local ini="${1:-$HALUI_INI}"
    if [ -n "${OPENEMC_TEST_MACHINE:-}" ]; then
        $OPENEMC_TEST_MACHINE "$ini" >&2 &
        MACHINE_PID=$!
    else
        realtime start || return 1
        SVR_PID=$(linuxcncsvr -ini "$ini" --daemon) || { realtime stop; return 1; }
        "$EMC2_HOME/objects/unit/nml_responder" -ini "$ini" &
        MACHINE_PID=$!
        halcmd loadusr -Wn halui halui -ini "$ini" || { stop_halui; return 1; }
    fi
    python3 - <<'PY' || { stop_halui; return 1; }
import sys, time
import hal, linuxcnc
s = linuxcnc.stat()
end = time.time() + 30
while time.time() < end:
    try:
        s.poll()
        if s.taskbeat > 0 and hal.get_p("halui.gui.jog-rate") is not None and s.max_velocity > 0:
            sys.exit(0)
    except (linuxcnc.error, RuntimeError, ValueError):
        pass
    time.sleep(0.02)
sys.stderr.write("machine or halui did not start\n")
sys.exit(1)
PY
}

# stop_halui: everything down again.
stop_halui() {
    if [ -n "${OPENEMC_TEST_MACHINE:-}" ]; then
        [ -n "${MACHINE_PID:-}" ] && kill "$MACHINE_PID" 2>/dev/null && wait "$MACHINE_PID" 2>/dev/null
        MACHINE_PID=
        return 0
    fi
    halcmd unload halui 2>/dev/null
    [ -n "${MACHINE_PID:-}" ] && kill "$MACHINE_PID" 2>/dev/null && wait "$MACHINE_PID" 2>/dev/null
    if [ -n "${SVR_PID:-}" ]; then
        kill "$SVR_PID" 2>/dev/null
        while kill -0 "$SVR_PID" 2>/dev/null; do sleep 0.02; done
    fi
    MACHINE_PID= SVR_PID=
    realtime stop
}
