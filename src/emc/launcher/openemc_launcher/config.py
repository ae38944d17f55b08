"""config: the INI values the launcher itself uses (step 4 of the start-up sequence)."""
import os
import shlex

from .errors import LaunchError
from .inicheck import parse_int

REQUIRED_VERSION = "1.1"


def load_ini(path):
    """Parse path with the INI library; its diagnostics (file:line: error: ...) are on stderr."""
    import _linuxcnc_ini
    try:
        return _linuxcnc_ini.ini(path)
    except _linuxcnc_ini.error:
        raise LaunchError("%s: error: the INI file cannot be used (see the messages above)" % path)


def words(text):
    """A command value split like a shell would (quotes group words)."""
    try:
        return shlex.split(text)
    except ValueError:
        return text.split()


class Config:
    """One configuration: its INI file and the values that drive the start-up."""

    def __init__(self, path, tree, opts):
        """Read path (absolute); opts supplies -t/-m overrides."""
        self.path = path
        self.directory = os.path.dirname(path)
        self.ini = load_ini(path)
        self.version = self.get("EMC", "VERSION")
        self.emcmot = self.get("MOT", "MOT") or self.get("EMCMOT", "EMCMOT") or "motmod"
        self.tpmod = opts.tpmod or self.get("TRAJ", "TPMOD") or "tpmod"
        self.homemod = opts.homemod or self.get("EMCMOT", "HOMEMOD") or "homemod"
        self.task = self.get("TASK", "TASK")
        self.halui = self.get("HAL", "HALUI")
        self.halbridge = self.get("HAL", "HALBRIDGE")
        self.display = self.get("DISPLAY", "DISPLAY")
        self.coordinates = self.get("TRAJ", "COORDINATES") or ""
        self.kinematics = self.get("KINS", "KINEMATICS") or ""
        self.nml_file = self._nml_file(tree)
        self.halfiles = self.ini.findall("HAL", "HALFILE")
        self.twopass = self.get("HAL", "TWOPASS") or ""
        self.halcmds = self.ini.findall("HAL", "HALCMD")
        self.shutdown = self.get("HAL", "SHUTDOWN")
        self.apps = self.ini.findall("APPLICATIONS", "APP")
        self.app_delay = self._app_delay()
        self.shmem_key = self._shmem_key()

    def get(self, section, key):
        """First value of [section]key, or None."""
        return self.ini.find(section, key)

    def where(self, section, key, num=1):
        """Location suffix of an entry for messages."""
        path, line = self.ini.lineof(section, key, num)
        if line is None:
            return ""
        if os.path.realpath(path) != os.path.realpath(self.path):
            return " (file %s line %d)" % (path, line)
        return " (line %d)" % line

    def error(self, section, key, what, num=1):
        """A LaunchError '<ini>: error: [SEC]KEY: what (line N)'."""
        return LaunchError("%s: error: [%s]%s: %s%s"
                           % (self.path, section, key, what, self.where(section, key, num)))

    def _nml_file(self, tree):
        """[LINUXCNC]NML_FILE, [EMC]NML_FILE (relative to the INI directory) or the default."""
        value = self.get("LINUXCNC", "NML_FILE") or self.get("EMC", "NML_FILE")
        if not value:
            return tree.default_nml
        value = os.path.expanduser(value)
        return os.path.normpath(value if os.path.isabs(value) else os.path.join(self.directory, value))

    def _app_delay(self):
        """[APPLICATIONS]DELAY in seconds (default 0); a non-number is an error."""
        text = self.get("APPLICATIONS", "DELAY")
        if text is None or text == "":
            return 0.0
        try:
            delay = float(text.split()[0])
        except ValueError:
            raise self.error("APPLICATIONS", "DELAY", "Invalid number '%s'" % text)
        if delay < 0:
            raise self.error("APPLICATIONS", "DELAY", "Must not be negative (%s)" % text)
        return delay

    def _shmem_key(self):
        """[EMCMOT]SHMEM_KEY (motion shared memory, default 100)."""
        text = self.get("EMCMOT", "SHMEM_KEY")
        try:
            return parse_int(text) if text and text.strip() else 100
        except ValueError:
            raise self.error("EMCMOT", "SHMEM_KEY", "Invalid integer '%s'" % text)

    def require(self):
        """Stop with an error when [EMC]VERSION, [TASK]TASK or [DISPLAY]DISPLAY is unusable."""
        if self.version != REQUIRED_VERSION:
            found = "missing" if self.version is None else "'%s'" % self.version
            raise LaunchError(
                "%s: error: [EMC]VERSION is %s%s; this launcher runs configurations of version "
                "%s only (convert older ones with LinuxCNC's update_ini first)"
                % (self.path, found, self.where("EMC", "VERSION"), REQUIRED_VERSION))
        if not self.task:
            raise self.error("TASK", "TASK", "Missing (the task program, normally milltask)")
        if not self.display:
            raise self.error("DISPLAY", "DISPLAY", "Missing (the display program, e.g. 'dummy')")
