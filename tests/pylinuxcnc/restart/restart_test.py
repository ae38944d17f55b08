"""restart_test.py: lazily attached channel objects across a machine restart (steered by test.sh)."""
import os
import time
import linuxcnc


def step(name):
    """Tell test.sh we reached a step."""
    open("step." + name, "w").close()


def wait_step(name):
    """Wait for test.sh to reach a step."""
    while not os.path.exists("step." + name):
        time.sleep(0.02)


s = linuxcnc.stat()
c = linuxcnc.command()
e = linuxcnc.error_channel()
for call in (s.poll, e.poll):
    try:
        call()
    except linuxcnc.error as err:
        print("before start:", err)
step("made")
wait_step("up1")
s.poll()
c.text_msg("first run")
print("first run:", s.task_state, e.poll(), len(s.tool_table) > 1)
step("polled")
wait_step("down")
for call in (s.poll, e.poll):
    try:
        call()
    except linuxcnc.error as err:
        print("machine down:", err)
print("command while down:", c.mode(linuxcnc.MODE_MDI))
step("failed")
wait_step("up2")
s.poll()
c.text_msg("second run")
print("second run:", s.task_state, e.poll(), len(s.tool_table) > 1, s.toolinfo(2)["diameter"])
