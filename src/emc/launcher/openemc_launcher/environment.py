"""environment: where the tree's programs and files are, and the variables the launcher exports."""
import os


class Tree:
    """Directories of the run-in-place tree the launcher belongs to (bin/linuxcnc -> top)."""

    def __init__(self, top):
        """top is the tree's top directory."""
        self.top = top
        self.bin = os.path.join(top, "bin")
        self.scripts = os.path.join(top, "scripts")
        self.lib = os.path.join(top, "lib")
        self.python = os.path.join(top, "lib", "python")
        self.hallib = os.path.join(top, "lib", "hallib")
        self.tcl = os.path.join(top, "lib", "tcl")
        self.rtlib = os.path.join(top, "rtlib")
        self.ncfiles = os.path.join(top, "nc_files")
        self.default_nml = os.path.join(top, "configs", "common", "linuxcnc.nml")

    @classmethod
    def of_program(cls, program):
        """The tree holding program (bin/linuxcnc or src/emc/launcher/linuxcnc)."""
        here = os.path.dirname(os.path.realpath(program))
        top = os.path.dirname(here)
        while not os.path.isdir(os.path.join(top, "bin")) and top != "/":
            top = os.path.dirname(top)
        return cls(top)

    def program(self, name):
        """bin/name when the tree built it, else name (found on PATH)."""
        path = os.path.join(self.bin, name)
        return path if os.access(path, os.X_OK) else name


def _prepend(env, var, *dirs):
    """Put dirs (in this order) in front of the colon list env[var], without duplicates."""
    old = [d for d in env.get(var, "").split(":") if d and d not in dirs]
    env[var] = ":".join(list(dirs) + old)


def hallib_path(hal_dirs, tree):
    """HALLIB_PATH: the -H dirs (last given first), the INI directory '.', then HALLIB_DIR."""
    return ":".join(list(hal_dirs) + [".", tree.hallib])


def base_environment(tree, opts, env=None):
    """The environment every started program sees (before the INI file is known)."""
    env = dict(os.environ if env is None else env)
    home_bin = os.path.join(os.path.expanduser("~"), ".local", "bin")
    _prepend(env, "PATH", tree.bin, tree.scripts, home_bin)
    _prepend(env, "PYTHONPATH", tree.python)
    _prepend(env, "TCLLIBPATH", tree.tcl)
    for var in ("LINUXCNC_HOME", "EMC2_HOME", "OPENEMC_HOME"):
        env[var] = tree.top
    env["LINUXCNC_BIN_DIR"] = tree.bin
    env["HALLIB_DIR"] = tree.hallib
    env["HALLIB_PATH"] = hallib_path(opts.hal_dirs, tree)
    env["HAL_RTMOD_DIR"] = env["LINUXCNC_RTLIB_DIR"] = tree.rtlib
    env["LINUXCNC_TCL_DIR"] = tree.tcl
    env["LINUXCNC_NCFILES_DIR"] = tree.ncfiles
    env["REALTIME"] = tree.program("realtime")
    env["HALCMD"] = "halcmd -k" if opts.keep_going else "halcmd"
    env["LINUXCNC_RIP_FLAG"] = "1"
    return env


def config_environment(env, config):
    """Add what the INI file decides: CONFIG_DIR, INI_FILE_NAME, NMLFILE, TRAJ/KINS exports."""
    env["CONFIG_DIR"] = config.directory
    _prepend(env, "PATH", os.path.join(config.directory, "bin"))
    env["INI_FILE_NAME"] = config.path
    env["NMLFILE"] = config.nml_file
    env["TRAJ_COORDINATES"] = config.coordinates
    env["KINS_KINEMATICS"] = config.kinematics
    return env
