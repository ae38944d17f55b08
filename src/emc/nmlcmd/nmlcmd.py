#!/usr/bin/env python3
"""nmlcmd: print the controller's status and send it commands from the shell, in the spirit of halcmd."""

import json
import os
import shlex
import sys
import time

# Run from the tree without rip-environment too: the module is in ../lib/python.
sys.path.append(os.path.join(os.path.dirname(os.path.dirname(os.path.realpath(__file__))), "lib", "python"))
import linuxcnc  # noqa: E402

USAGE = """Usage: nmlcmd [OPTIONS] COMMAND [ARGS...]
       nmlcmd [OPTIONS] -f FILE       (one command per line; '-' reads stdin)
Options:
  -ini INIFILE   use [EMC]NML_FILE of this configuration (default: the shipped linuxcnc.nml)
  -nml NMLFILE   use this .nml file
  -w             wait for each command to complete; a rejected command makes the exit status 1
  -t SECONDS     timeout of -w and of 'wait' (default 5)
  -k             keep going after a failed command in -f mode
Commands:
  status [--json] [NAME...]     the whole status, or the named stat attributes
  watch [-i SECONDS] NAME...    print the named attributes whenever they change (Ctrl-C ends)
  errors [--follow]             print error-channel messages (and keep waiting with --follow)
  wait                          wait for the last command of this session to complete
  state estop|estop_reset|on|off
  mode manual|auto|mdi
  mdi TEXT...                   send one MDI line
  abort | home JOINT|all | unhome JOINT|all
  open FILE | run [LINE] | pause | resume | step
  feedrate SCALE | rapidrate SCALE | maxvel VELOCITY | spindleoverride SCALE
  flood on|off | mist on|off | spindle forward|reverse|off [RPM]
  msg text|display|error TEXT...
  tools                         the tool table as published by task
The machine is the one of $OPENEMC_INSTANCE (default 0), as for halcmd.
"""

ENUMS = {
    "task_state": "STATE_", "task_mode": "MODE_", "interp_state": "INTERP_",
    "exec_state": "EXEC_", "state": "RCS_", "motion_mode": "TRAJ_MODE_",
    "motion_type": "MOTION_TYPE_", "kinematics_type": "KINEMATICS_",
}
SKIP = {"poll", "toolinfo"}


class Failure(Exception):
    """A command that could not be carried out; its text is printed."""


def enum_name(attr, value):
    """Symbolic name of an enumerated attribute value, e.g. STATE_ESTOP."""
    prefix = ENUMS.get(attr)
    if prefix is None:
        return None
    for name in dir(linuxcnc):
        if name.startswith(prefix) and getattr(linuxcnc, name) == value:
            return name
    return None


def attributes(stat):
    """Names of the readable status attributes."""
    return sorted(n for n in dir(stat) if not n.startswith("_") and n not in SKIP)


def plain(value):
    """A JSON-friendly copy of an attribute value."""
    if isinstance(value, tuple) and hasattr(value, "n_fields"):
        return list(value)
    if isinstance(value, (tuple, list)):
        return [plain(v) for v in value]
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    return value


class Session:
    """The channels and settings of one nmlcmd run."""

    def __init__(self, opts):
        """Remember options; channels are made on first use."""
        self.opts = opts
        self.stat = linuxcnc.stat()
        self.command = linuxcnc.command()
        self.errors = None
        self.sent = False

    def poll(self):
        """Fresh status, or Failure when no machine runs."""
        try:
            self.stat.poll()
        except linuxcnc.error as e:
            raise Failure("no machine is running in instance %s (%s)" % (instance(), e))
        return self.stat

    def send(self, method, *args):
        """Call a command method; with -w wait for it and fail on RCS_ERROR."""
        self.poll()
        try:
            getattr(self.command, method)(*args)
        except (ValueError, TypeError, linuxcnc.error) as e:
            raise Failure(str(e))
        self.sent = True
        if self.opts["wait"]:
            self.wait()

    def wait(self):
        """wait_complete with the session timeout."""
        result = self.command.wait_complete(self.opts["timeout"])
        if result == linuxcnc.RCS_ERROR:
            raise Failure("command was rejected (RCS_ERROR); see 'nmlcmd errors'")
        if result == -1:
            raise Failure("timed out after %g s waiting for completion" % self.opts["timeout"])


def instance():
    """This process's instance number, as the libraries see it."""
    return os.environ.get("OPENEMC_INSTANCE", "0")


def format_value(attr, value):
    """Text of one attribute for the status listing."""
    name = enum_name(attr, value)
    if name:
        return "%s (%d)" % (name, value)
    if isinstance(value, float):
        return "%.6g" % value
    if isinstance(value, tuple) and value and isinstance(value[0], float):
        return "(" + ", ".join("%.6g" % v for v in value) + ")"
    return repr(value)


def cmd_status(sess, args):
    """status [--json] [NAME...]"""
    as_json = "--json" in args
    names = [a for a in args if a != "--json"] or attributes(sess.stat)
    s = sess.poll()
    for n in names:
        if not hasattr(s, n) or n in SKIP:
            raise Failure("unknown status attribute '%s'" % n)
    if as_json:
        print(json.dumps({n: plain(getattr(s, n)) for n in names}, indent=1, sort_keys=True))
        return
    width = max(len(n) for n in names)
    for n in names:
        print("%-*s  %s" % (width, n, format_value(n, getattr(s, n))))


def cmd_watch(sess, args):
    """watch [-i SECONDS] NAME..."""
    interval = 0.1
    if args[:1] == ["-i"]:
        interval = float(args[1])
        args = args[2:]
    if not args:
        raise Failure("watch: name at least one status attribute")
    last = None
    try:
        while True:
            s = sess.poll()
            now = tuple(getattr(s, n) for n in args)
            if now != last:
                print(" ".join("%s=%s" % (n, format_value(n, v)) for n, v in zip(args, now)), flush=True)
                last = now
            time.sleep(interval)
    except KeyboardInterrupt:
        return


def cmd_errors(sess, args):
    """errors [--follow]"""
    kinds = {linuxcnc.OPERATOR_ERROR: "error", linuxcnc.OPERATOR_TEXT: "text",
             linuxcnc.OPERATOR_DISPLAY: "display", linuxcnc.NML_ERROR: "error",
             linuxcnc.NML_TEXT: "text", linuxcnc.NML_DISPLAY: "display"}
    sess.errors = sess.errors or linuxcnc.error_channel()
    follow = "--follow" in args
    try:
        while True:
            try:
                msg = sess.errors.poll()
            except linuxcnc.error as e:
                raise Failure("no machine is running in instance %s (%s)" % (instance(), e))
            if msg:
                print("%s: %s" % (kinds.get(msg[0], str(msg[0])), msg[1].rstrip("\n")), flush=True)
            elif not follow:
                return
            else:
                time.sleep(0.05)
    except KeyboardInterrupt:
        return


def choice(word, table, what):
    """Look a keyword up in table or fail naming the choices."""
    key = word.lower() if word else ""
    if key not in table:
        raise Failure("%s must be one of %s, not '%s'" % (what, ", ".join(sorted(table)), word))
    return table[key]


def joint_arg(word):
    """A joint number, or -1 for 'all'."""
    if word == "all":
        return -1
    try:
        return int(word)
    except (TypeError, ValueError):
        raise Failure("joint must be a number or 'all', not '%s'" % word)


def number(word, what):
    """A float argument."""
    try:
        return float(word)
    except (TypeError, ValueError):
        raise Failure("%s must be a number, not '%s'" % (what, word))


def cmd_tools(sess, _args):
    """tools"""
    s = sess.poll()
    print("%5s %5s %10s %10s %10s  %s" % ("index", "tool", "z", "x", "diameter", "comment"))
    for i, t in enumerate(s.tool_table):
        comment = ""
        if i > 0 and t.id > 0:
            try:
                comment = s.toolinfo(t.id)["comment"]
            except ValueError:
                comment = ""
        print("%5d %5d %10.4f %10.4f %10.4f  %s" % (i, t.id, t.zoffset, t.xoffset, t.diameter, comment))


def simple_commands():
    """Commands that map onto one command method: name -> (arity, call builder)."""
    on_off = {"on": 1, "off": 0}
    spindle_dirs = {"forward": linuxcnc.SPINDLE_FORWARD, "reverse": linuxcnc.SPINDLE_REVERSE,
                    "off": linuxcnc.SPINDLE_OFF}
    return {
        "state": (1, lambda a: ("state", choice(a[0], {"estop": linuxcnc.STATE_ESTOP,
                                                       "estop_reset": linuxcnc.STATE_ESTOP_RESET,
                                                       "on": linuxcnc.STATE_ON, "off": linuxcnc.STATE_OFF}, "state"))),
        "mode": (1, lambda a: ("mode", choice(a[0], {"manual": linuxcnc.MODE_MANUAL, "auto": linuxcnc.MODE_AUTO,
                                                     "mdi": linuxcnc.MODE_MDI}, "mode"))),
        "abort": (0, lambda a: ("abort",)),
        "home": (1, lambda a: ("home", joint_arg(a[0]))),
        "unhome": (1, lambda a: ("unhome", joint_arg(a[0]))),
        "open": (1, lambda a: ("program_open", a[0])),
        "pause": (0, lambda a: ("auto", linuxcnc.AUTO_PAUSE)),
        "resume": (0, lambda a: ("auto", linuxcnc.AUTO_RESUME)),
        "step": (0, lambda a: ("auto", linuxcnc.AUTO_STEP)),
        "feedrate": (1, lambda a: ("feedrate", number(a[0], "scale"))),
        "rapidrate": (1, lambda a: ("rapidrate", number(a[0], "scale"))),
        "maxvel": (1, lambda a: ("maxvel", number(a[0], "velocity"))),
        "spindleoverride": (1, lambda a: ("spindleoverride", number(a[0], "scale"))),
        "flood": (1, lambda a: ("flood", choice(a[0], on_off, "flood"))),
        "mist": (1, lambda a: ("mist", choice(a[0], on_off, "mist"))),
        "spindle": (-1, lambda a: ("spindle", choice(a[0] if a else None, spindle_dirs, "direction"))
                    + ((number(a[1], "speed"),) if len(a) > 1 else ())),
    }


def run_command(sess, words):
    """Execute one command line (already split)."""
    name, args = words[0], words[1:]
    direct = {"status": cmd_status, "watch": cmd_watch, "errors": cmd_errors, "tools": cmd_tools}
    if name in direct:
        return direct[name](sess, args)
    if name == "wait":
        return sess.wait()
    if name == "mdi":
        if not args:
            raise Failure("mdi: give the MDI text")
        return sess.send("mdi", " ".join(args))
    if name == "run":
        return sess.send("auto", linuxcnc.AUTO_RUN, int(number(args[0], "line")) if args else 0)
    if name == "msg":
        kind = choice(args[0] if args else None, {"text": "text_msg", "display": "display_msg",
                                                  "error": "error_msg"}, "message kind")
        return sess.send(kind, " ".join(args[1:]))
    table = simple_commands()
    if name not in table:
        raise Failure("unknown command '%s' (see nmlcmd -h)" % name)
    arity, build = table[name]
    if arity >= 0 and len(args) != arity:
        raise Failure("%s takes %d argument%s" % (name, arity, "" if arity == 1 else "s"))
    return sess.send(*build(args))


def parse_options(argv):
    """Options before the command; returns (options, remaining words)."""
    opts = {"wait": False, "timeout": 5.0, "file": None, "keep": False}
    i = 0
    while i < len(argv) and argv[i].startswith("-"):
        a = argv[i]
        if a in ("-h", "--help"):
            sys.stdout.write(USAGE)
            sys.exit(0)
        elif a == "-w":
            opts["wait"] = True
        elif a == "-k":
            opts["keep"] = True
        elif a in ("-ini", "-nml", "-t", "-f") and i + 1 < len(argv):
            opts[{"-ini": "ini", "-nml": "nml", "-t": "t", "-f": "file"}[a]] = argv[i + 1]
            i += 1
        else:
            raise Failure("unknown option '%s' (see nmlcmd -h)" % a)
        i += 1
    opts["timeout"] = number(opts.get("t", opts["timeout"]), "timeout")
    return opts, argv[i:]


def select_nml(opts):
    """Point the linuxcnc module at the configuration's .nml file."""
    if opts.get("nml"):
        linuxcnc.nmlfile = opts["nml"]
    elif opts.get("ini"):
        ini = linuxcnc.ini(opts["ini"])
        nml = ini.find("EMC", "NML_FILE")
        if nml:
            linuxcnc.nmlfile = nml if nml.startswith("/") else os.path.join(os.path.dirname(opts["ini"]), nml)


def run_script(sess, path, keep):
    """-f FILE: one command per line, '#' comments; file:line: on errors."""
    stream = sys.stdin if path == "-" else open(path)
    failed = 0
    with stream:
        for lineno, line in enumerate(stream, 1):
            words = shlex.split(line, comments=True)
            if not words:
                continue
            try:
                run_command(sess, words)
            except Failure as e:
                sys.stderr.write("%s:%d: %s\n" % ("<stdin>" if path == "-" else path, lineno, e))
                failed = 1
                if not keep:
                    return 1
    return failed


def main(argv):
    """Entry point; returns the exit status."""
    try:
        opts, words = parse_options(argv)
        select_nml(opts)
        sess = Session(opts)
        if opts["file"]:
            return run_script(sess, opts["file"], opts["keep"])
        if not words:
            sys.stderr.write(USAGE)
            return 1
        run_command(sess, words)
        return 0
    except Failure as e:
        sys.stderr.write("nmlcmd: %s\n" % e)
        return 1
    except linuxcnc.error as e:
        sys.stderr.write("nmlcmd: %s\n" % e)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
