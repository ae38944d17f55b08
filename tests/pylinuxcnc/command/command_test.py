"""command_test.py: linuxcnc.command against task (or its stand-in): nml.md sec. 2 and 4."""
import os
import tempfile
import linuxcnc

s = linuxcnc.stat()
c = linuxcnc.command()
c2 = linuxcnc.command()
e = linuxcnc.error_channel()


def drain():
    """Every message waiting on the error channel."""
    out = []
    while True:
        m = e.poll()
        if not m:
            return out
        out.append(m)


def status():
    """(task_state, task_mode, rcs state) after a poll."""
    s.poll()
    return s.task_state, s.task_mode, s.state


drain()
print("== serials")
c.debug(0)
first = c.serial
c2.debug(0)
c.debug(0)
c2.debug(0)
print("alternating objects:", [c2.serial - first, c.serial - first])
s.poll()
print("echo is the last serial:", s.echo_serial_number == c2.serial)
print("wait_complete(0):", c.wait_complete(0))
print("wait_complete():", c.wait_complete())

print("== rejected in E-stop")
c.home(0)
print("home in estop:", c.wait_complete(), drain())
s.poll()
print("status stays ERROR:", s.state)
c.debug(0)
print("next command clears it:", c.wait_complete(), status()[2])

print("== machine on")
c.state(linuxcnc.STATE_ON)
print("ON from ESTOP is ignored:", c.wait_complete(), status()[0], drain())
c.state(linuxcnc.STATE_ESTOP_RESET)
c.wait_complete()
print("after ESTOP_RESET:", status()[0])
c.state(linuxcnc.STATE_ON)
c.wait_complete()
print("after ON:", status()[0], s.enabled, s.estop)

print("== modes")
c.mode(linuxcnc.MODE_MDI)
print("MDI:", c.wait_complete(), status()[1], s.motion_mode)
c.mdi("G0 X1")
print("MDI unhomed:", c.wait_complete(), drain())
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
print("MANUAL unhomed:", status()[1], s.motion_mode)
c.traj_mode(linuxcnc.TRAJ_MODE_COORD)
print("traj_mode:", c.wait_complete(), drain())
c.home(-1)
c.wait_complete()
while not all(status() and s.homed[:s.joints]):
    pass
print("homed:", s.homed[:s.joints])
c.mode(linuxcnc.MODE_MANUAL)
c.wait_complete()
print("MANUAL homed:", status()[1], s.motion_mode)
c.mode(linuxcnc.MODE_MDI)
c.wait_complete()
c.mdi("G0 X0.5 Y0.25")
print("MDI move:", c.wait_complete(), drain())
s.poll()
print("position:", s.position[:3], "interp:", s.interp_state, "command:", repr(s.command))
c.mdi("G4 P0.5")
print("dwell, short wait:", c.wait_complete(0.1))
s.poll()
print("while dwelling:", s.exec_state, s.interp_state, s.state)
print("dwell, long wait:", c.wait_complete(5))
c.mdi("M2")
print("M2 in MDI:", c.wait_complete(), drain())
c.mdi("")
print("empty MDI:", c.wait_complete())

print("== overrides and flags")
c.feedrate(1.5)
c.rapidrate(-1)
c.maxvel(2.5)
c.spindleoverride(0.8)
c.set_optional_stop(0)
c.set_block_delete(0)
c.set_feed_override(0)
c.set_adaptive_feed(1)
c.set_feed_hold(0)
c.debug(5)
c.wait_complete()
s.poll()
print("feed/rapid/maxvel:", s.feedrate, s.rapidrate, s.max_velocity)
print("spindle override:", s.spindle[0]["override"])
print("flags:", s.optional_stop, s.block_delete, s.feed_override_enabled,
      s.adaptive_feed_enabled, s.feed_hold_enabled, s.debug)

print("== spindle, coolant, I/O")
c.spindle(linuxcnc.SPINDLE_REVERSE, 300)
c.wait_complete()
s.poll()
print("reverse 300:", s.spindle[0]["speed"], s.spindle[0]["direction"], s.spindle[0]["brake"])
c.spindle(linuxcnc.SPINDLE_OFF)
c.wait_complete()
s.poll()
print("off:", s.spindle[0]["speed"], s.spindle[0]["direction"], s.spindle[0]["brake"])
c.spindle(linuxcnc.SPINDLE_FORWARD, 100, 3)
print("non-existent spindle:", c.wait_complete(), drain())
c.flood(linuxcnc.FLOOD_ON)
c.mist(linuxcnc.MIST_ON)
c.wait_complete()
s.poll()
print("coolant:", s.flood, s.mist)
c.set_digital_output(1, 1)
c.set_analog_output(2, 1.25)
c.wait_complete()
s.poll()
print("dout/aout:", s.dout[:4], s.aout[:4])
c.set_digital_output(10, 1)
print("dout out of range:", c.wait_complete(), drain())

print("== programs")
fd, path = tempfile.mkstemp(suffix=".ngc")
os.write(fd, b"G0 X1\nG0 Y1\nM2\n")
os.close(fd)
before = c.serial
c.mode(linuxcnc.MODE_AUTO)
c.program_open(path)
print("program_open uses two serials:", c.serial - before - 1, c.wait_complete())
s.poll()
print("file:", s.file == path)
c.auto(linuxcnc.AUTO_RUN, 0)
c.wait_complete(0.2)
c.mode(linuxcnc.MODE_AUTO)
c.wait_complete()
while status() and s.interp_state != linuxcnc.INTERP_IDLE:
    pass
print("ran to the end:", s.interp_state, s.task_mode)
c.program_open("/no/such/prog.ngc")
print("open missing:", c.wait_complete(), drain())
os.unlink(path)

print("== operator messages")
c.text_msg("a text")
c.display_msg("a display")
c.error_msg("x" * 300)
c.wait_complete()
msgs = drain()
print("kinds:", [m[0] for m in msgs], "texts:", [m[1][:9] for m in msgs], "lengths:", [len(m[1]) for m in msgs])

print("== abort and estop")
c.mode(linuxcnc.MODE_MDI)
c.mdi("G4 P5")
c.abort()
print("abort:", c.wait_complete(), status()[2], s.interp_state, repr(s.command))
c.state(linuxcnc.STATE_ESTOP)
c.wait_complete()
print("estop:", status()[0], s.enabled)
