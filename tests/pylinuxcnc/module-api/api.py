"""api.py: linuxcnc module surface that needs no running machine (python.md sec. 1)."""
import os
import linuxcnc


def show(label, value):
    """Print one labelled result."""
    print("%s: %r" % (label, value))


def outcome(call):
    """Run call; return its result or the exception class and text."""
    try:
        return call()
    except Exception as e:  # noqa: BLE001 - the test prints whatever is raised
        return "%s: %s" % (type(e).__name__, e)


show("version", linuxcnc.version)
show("SHARE is PREFIX/share", linuxcnc.SHARE == linuxcnc.PREFIX + "/share")
show("nmlfile", os.path.relpath(linuxcnc.nmlfile, linuxcnc.PREFIX))
show("error", (linuxcnc.error.__name__, linuxcnc.error.__module__, issubclass(linuxcnc.error, RuntimeError)))
for name in ("stat", "command", "error_channel", "ini", "positionlogger"):
    t = getattr(linuxcnc, name)
    show(name, (t.__name__, outcome(lambda: type("Sub", (t,), {}) and "subclassable")))
show("tool", (linuxcnc.tool.__name__, linuxcnc.tool.n_fields))

groups = ["MODE_", "STATE_", "INTERP_", "EXEC_", "RCS_", "TRAJ_MODE_", "MOTION_TYPE_",
          "KINEMATICS_", "SPINDLE_", "MIST_", "FLOOD_", "BRAKE_", "JOG_", "AUTO_",
          "OPERATOR_", "NML_", "MAX_", "DEBUG_"]
names = sorted(n for n in dir(linuxcnc) if any(n.startswith(g) for g in groups))
for n in names + ["LINEAR", "ANGULAR"]:
    print("%s = %r" % (n, getattr(linuxcnc, n)))

s = linuxcnc.stat()
show("fresh stat", (s.task_state, s.echo_serial_number, s.file, s.position[:3], s.tool_table))
show("stat.poll", outcome(s.poll))
show("toolinfo before poll", outcome(lambda: s.toolinfo(1)))
e = linuxcnc.error_channel()
show("error_channel.poll", outcome(e.poll))
c = linuxcnc.command()
show("mode when not running", (c.mode(linuxcnc.MODE_MDI), c.serial))
show("wait_complete", c.wait_complete(0.05))

checks = [
    ("mode(9)", lambda: c.mode(9)),
    ("state(0)", lambda: c.state(0)),
    ("flood(2)", lambda: c.flood(2)),
    ("mist(5)", lambda: c.mist(5)),
    ("brake(3)", lambda: c.brake(3)),
    ("spindle(7)", lambda: c.spindle(7)),
    ("mdi(255 chars)", lambda: c.mdi("G" * 255)),
    ("program_open(255 chars)", lambda: c.program_open("/" + "x" * 254)),
    ("auto(AUTO_RUN)", lambda: c.auto(linuxcnc.AUTO_RUN)),
    ("auto(99)", lambda: c.auto(99)),
    ("auto(AUTO_PAUSE, 1)", lambda: c.auto(linuxcnc.AUTO_PAUSE, 1)),
    ("jog(JOG_STOP, 0, 0, 1)", lambda: c.jog(linuxcnc.JOG_STOP, 0, 0, 1)),
    ("jog(JOG_CONTINUOUS, 0, 0)", lambda: c.jog(linuxcnc.JOG_CONTINUOUS, 0, 0)),
    ("jog(JOG_INCREMENT, 0, 0, 1)", lambda: c.jog(linuxcnc.JOG_INCREMENT, 0, 0, 1)),
    ("jog(7, 0, 0)", lambda: c.jog(7, 0, 0)),
    ("set_digital_output(-1, 0)", lambda: c.set_digital_output(-1, 0)),
    ("set_digital_output(1, 300)", lambda: c.set_digital_output(1, 300)),
    ("wait_complete('x')", lambda: c.wait_complete("x")),
    ("ini missing", lambda: linuxcnc.ini("/no/such/file.ini")),
]
for label, call in checks:
    show(label, outcome(call))
show("valid calls send nothing", (c.mdi("G0 X1"), c.jog(linuxcnc.JOG_STOP, True, 0), c.serial))
show("vertex9", linuxcnc.vertex9("XYZ", (1, 2, 3, 0, 0, 0, 0, 0, 0)))
show("vertex9 rotary", tuple(round(v, 9) for v in linuxcnc.vertex9("XYZC", (1, 0, 0, 0, 0, 90, 0, 0, 0))))
show("vertex9 reversed", tuple(round(v, 9) for v in linuxcnc.vertex9("XYZ-C", (1, 0, 0, 0, 0, 90, 0, 0, 0))))
