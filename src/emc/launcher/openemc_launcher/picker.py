"""picker: the INI file to start when none is named: the last one used (-l, '-') or a choice
from a text menu of the known configurations (~/linuxcnc/configs and the tree's configs/sim)."""
import glob
import os
import sys

from .errors import LaunchError

RC_FILE = os.path.join("~", ".linuxcncrc")


def last_config():
    """[PICKCONFIG]LAST_CONFIG of ~/.linuxcncrc, or a LaunchError."""
    import _linuxcnc_ini
    path = os.path.expanduser(RC_FILE)
    if not os.path.exists(path):
        raise LaunchError("linuxcnc: no configuration was used before (%s does not exist); "
                          "name an INI file" % path)
    try:
        value = _linuxcnc_ini.ini(path).find("PICKCONFIG", "LAST_CONFIG")
    except _linuxcnc_ini.error:
        raise LaunchError("linuxcnc: %s cannot be read (see the messages above)" % path)
    if not value:
        raise LaunchError("%s: error: [PICKCONFIG]LAST_CONFIG: Missing" % path)
    return os.path.expanduser(value)


def remember(path):
    """Store path as [PICKCONFIG]LAST_CONFIG in ~/.linuxcncrc (temporary file and rename)."""
    rc = os.path.expanduser(RC_FILE)
    tmp = "%s.tmp%d" % (rc, os.getpid())
    try:
        with open(tmp, "w") as f:
            f.write("[PICKCONFIG]\nLAST_CONFIG = %s\n" % path)
        os.replace(tmp, rc)
    except OSError as e:
        sys.stderr.write("linuxcnc: cannot write %s: %s\n" % (rc, e.strerror))


def candidates(tree):
    """Known configurations: the user's (~/linuxcnc/configs) first, then the tree's sims."""
    user = os.path.expanduser(os.path.join("~", "linuxcnc", "configs"))
    found = sorted(glob.glob(os.path.join(user, "*", "*.ini")))
    found += sorted(glob.glob(os.path.join(user, "*", "*.demo")))
    found += sorted(glob.glob(os.path.join(tree.top, "configs", "sim", "**", "*.ini"),
                              recursive=True))
    return found


def pick(tree):
    """Ask on the terminal which configuration to start; the chosen path (remembered)."""
    if not (sys.stdin.isatty() and sys.stdout.isatty()):
        raise LaunchError("linuxcnc: no INI file given and no terminal to choose one on; "
                          "run 'linuxcnc <INI-file>'")
    configs = candidates(tree)
    if not configs:
        raise LaunchError("linuxcnc: no configurations found; run 'linuxcnc <INI-file>'")
    sys.stdout.write("Configurations:\n")
    for number, path in enumerate(configs, 1):
        sys.stdout.write("  %2d  %s\n" % (number, path))
    sys.stdout.write("Start which one (number, empty to quit)? ")
    sys.stdout.flush()
    answer = sys.stdin.readline().strip()
    if not answer:
        raise LaunchError("linuxcnc: nothing chosen", status=0)
    if not answer.isdigit() or not 1 <= int(answer) <= len(configs):
        raise LaunchError("linuxcnc: '%s' is not one of the numbers 1..%d"
                          % (answer, len(configs)))
    chosen = configs[int(answer) - 1]
    remember(chosen)
    if chosen.endswith(".demo"):
        os.execv(chosen, [chosen])
    return chosen
