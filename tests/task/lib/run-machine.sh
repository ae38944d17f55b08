# run-machine.sh: sourced by the task tests: start test.ini (or the INI given) with its test-ui.py
# display, print what the display wrote to ui.out, and check that nothing of the machine is left
# afterwards.
run_machine() {
    local ini=${1:-test.ini}
    rm -f ui.out
    cp tool.tbl.in tool.tbl 2>/dev/null
    linuxcnc -r "$ini" > launcher.log 2>&1
    local rc=$?
    [ -f ui.out ] && cat ui.out
    if [ $rc -ne 0 ]; then
        echo "linuxcnc exited with $rc" >&2
        cat launcher.log >&2
        return 1
    fi
    if pgrep -f "milltask -ini .*$(basename "$PWD")/$ini" > /dev/null; then
        echo "milltask still running after linuxcnc exited"
        return 1
    fi
    if realtime status > /dev/null 2>&1; then
        echo "realtime still running after linuxcnc exited"
        return 1
    fi
    return 0
}
