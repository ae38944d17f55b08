"""display: the [DISPLAY]DISPLAY program (or the headless 'dummy' display) and [APPLICATIONS]."""
import os
import shutil
import signal
import subprocess
import sys
import time

from .config import words

DUMMY = "dummy"


def find_program(name, env, config_dir, ini_dir_first):
    """Absolute path of a program: absolute names as given, names with '/' relative to the INI
    directory, others on PATH (after the INI directory itself when ini_dir_first)."""
    if os.path.isabs(name):
        return name if os.access(name, os.X_OK) else None
    if "/" in name:
        path = os.path.normpath(os.path.join(config_dir, name))
        return path if os.access(path, os.X_OK) else None
    if ini_dir_first:
        path = os.path.join(config_dir, name)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return shutil.which(name, path=env.get("PATH", ""))


def display_argv(config, opts, env):
    """The display command line, [] for 'dummy'; raises when the program cannot be found."""
    parts = words(config.display)
    program, args = parts[0], parts[1:]
    if program == DUMMY:
        return []
    path = find_program(program, env, config.directory, False)
    if path is None:
        raise config.error("DISPLAY", "DISPLAY", "program '%s' not found (OpenEMC ships no "
                           "graphical display; use 'dummy', 'linuxcncrsh' or a program on PATH)"
                           % program)
    if program == "linuxcncrsh":
        return [path] + args + opts.display_args + ["--", "-ini", config.path]
    return [path, "-ini", config.path] + args + opts.display_args


def wait_dummy(tell):
    """Headless display: wait for Enter on a terminal (or a line on stdin), else for a signal."""
    tell("linuxcnc: running headless ([DISPLAY]DISPLAY = dummy); press Enter, or send SIGINT or "
         "SIGTERM to pid %d, to stop" % os.getpid())
    try:
        line = sys.stdin.readline()
    except (OSError, ValueError):
        line = ""
    if line:
        return 0
    while True:
        signal.pause()


def run_display(argv, children, tell):
    """Run the display in the foreground and return its exit status (128+N when killed)."""
    if not argv:
        return wait_dummy(tell)
    proc = children.start("display", argv)
    while True:
        try:
            status = proc.wait(timeout=0.2)
            break
        except subprocess.TimeoutExpired:
            children.reap()
    return 128 - status if status < 0 else status


SPLASH = """
wm overrideredirect . 1
image create photo splash -file {%s}
label .l -image splash -borderwidth 0
pack .l
update idletasks
wm geometry . +[expr {([winfo screenwidth .] - [winfo reqwidth .]) / 2}]+[expr {([winfo screenheight .] - [winfo reqheight .]) / 2}]
after %d exit
"""


def start_splash(config, env, children):
    """[DISPLAY]INTRO_GRAPHIC for INTRO_TIME seconds (default 5), when there is an X display."""
    image = config.get("DISPLAY", "INTRO_GRAPHIC")
    wish = shutil.which("wish", path=env.get("PATH", ""))
    if not image or not env.get("DISPLAY") or not wish:
        return
    path = image if os.path.isabs(image) else os.path.join(config.directory, image)
    if not os.path.isfile(path):
        return
    try:
        seconds = float((config.get("DISPLAY", "INTRO_TIME") or "5").split()[0])
    except ValueError:
        seconds = 5.0
    proc = children.start("splash", [wish], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL)
    proc.stdin.write((SPLASH % (path, int(seconds * 1000))).encode())
    proc.stdin.close()


def start_applications(config, env, children, tell):
    """[APPLICATIONS]: wait DELAY seconds, then start each APP in the background."""
    if not config.apps:
        return
    if config.app_delay > 0:
        time.sleep(config.app_delay)
    for num, value in enumerate(config.apps, 1):
        parts = words(value)
        if not parts:
            continue
        path = find_program(parts[0], env, config.directory, True)
        if path is None:
            tell("%s: error: [APPLICATIONS]APP: program '%s' not found, not started%s"
                 % (config.path, parts[0], config.where("APPLICATIONS", "APP", num)))
            continue
        children.start("app%d" % num, [path] + parts[1:])
