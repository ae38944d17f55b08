"""options: the command line of `linuxcnc [options] [INI | -] [display args...]`."""
import os
import sys
from dataclasses import dataclass, field

from .errors import LaunchError

USAGE = """\
Usage: linuxcnc [options] [<INI-file> | -] [display arguments...]

Start the machine configuration <INI-file>: NML server, realtime, task, HAL
files and the [DISPLAY]DISPLAY program; when the display exits everything is
stopped again. '-' (or -l) starts the configuration used last.

Options:
  -d          debug: show every step and command (output stays on the terminal)
  -v          verbose: say what is started (output stays on the terminal)
  -r          keep output on the terminal even when stdin is not a terminal
              (no temporary log files; used by tests)
  -l          use the INI file used last (~/.linuxcncrc [PICKCONFIG]LAST_CONFIG)
  -k          continue when a HAL file fails (halcmd -k)
  -t "mod [args]"  trajectory planner module instead of [TRAJ]TPMOD
  -m "mod [args]"  homing module instead of [EMCMOT]HOMEMOD
  -H dir      search dir first for HAL files (repeatable; last given first)
  -h          this help

Each configuration runs in its own OPENEMC_INSTANCE (HAL, NML and motion
shared memory); two configurations can run side by side. Without
OPENEMC_INSTANCE the first free instance from 0 up is used and reported.
"""


@dataclass
class Options:
    """What the command line asked for."""
    debug: bool = False
    verbose: bool = False
    no_redirect: bool = False
    last_config: bool = False
    keep_going: bool = False
    tpmod: str = None
    homemod: str = None
    hal_dirs: list = field(default_factory=list)
    ini: str = None
    display_args: list = field(default_factory=list)


FLAGS = {"d": "debug", "v": "verbose", "r": "no_redirect", "l": "last_config", "k": "keep_going"}
VALUED = {"t": "tpmod", "m": "homemod", "H": "hal_dirs"}


def _take_value(word, letter, rest):
    """The value of a valued option: attached (-tfoo) or the next word."""
    if len(word) > 2:
        return word[2:]
    if not rest:
        raise LaunchError("linuxcnc: option -%s needs a value\n%s" % (letter, USAGE))
    return rest.pop(0)


def _add_hal_dir(opts, value):
    """-H dir: must be a directory; prepends its real path to the HAL file search."""
    if not os.path.isdir(value):
        raise LaunchError("Invalid dirname specified: -H %s" % value)
    opts.hal_dirs.insert(0, os.path.realpath(value))


def parse(argv):
    """Options from argv (without the program name); -h prints the help and exits 0."""
    opts, rest = Options(), list(argv)
    while rest and rest[0].startswith("-") and rest[0] != "-":
        word = rest.pop(0)
        if word == "--":
            break
        letter = word[1]
        if letter == "h" or word == "--help":
            sys.stdout.write(USAGE)
            sys.exit(0)
        if letter in VALUED:
            value = _take_value(word, letter, rest)
            if letter == "H":
                _add_hal_dir(opts, value)
            else:
                setattr(opts, VALUED[letter], value)
            continue
        if letter not in FLAGS:
            raise LaunchError("linuxcnc: unknown option '%s'\n%s" % (word, USAGE))
        for flag in word[1:]:
            if flag not in FLAGS:
                raise LaunchError("linuxcnc: unknown option '-%s'\n%s" % (flag, USAGE))
            setattr(opts, FLAGS[flag], True)
    if rest:
        opts.ini = rest.pop(0)
        opts.display_args = rest
    if opts.ini == "-":
        opts.ini, opts.last_config = None, True
    return opts
