"""halfiles: finding and running [HAL]HALFILE (plain, LIB: or the HALLIB_PATH search), twopass,
[HAL]HALCMD and [HAL]SHUTDOWN."""
import os
import sys

from .errors import LaunchError


def out(text):
    """Launcher progress text on stdout (the 'Found file' lines LinuxCNC prints)."""
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def split_value(value):
    """A HALFILE value split into (file, [args]) at blanks; '~' expanded in the file name."""
    words = value.split()
    if not words:
        return "", []
    return os.path.expanduser(words[0]), words[1:]


def readable_file(path):
    """True for a readable regular file (a dangling link or a directory is not one)."""
    return os.path.isfile(path) and os.access(path, os.R_OK)


def resolve(name, hallib_dir, search_path):
    """The path a HALFILE name refers to; None when a relative name is found nowhere."""
    if name.startswith("LIB:"):
        lib_name = name[4:]
        if not lib_name:
            out("ILLFORMED LIB:file:<%s>" % name)
            return None
        path = os.path.join(hallib_dir, lib_name)
        if not readable_file(path):
            out("CANNOT READ LIB:file:%s" % path)
        out("Found file(LIB): %s" % path)
        return path
    if name.startswith("/"):
        out("Found file(ABS): %s" % name)
        return name
    for directory in search_path.split(":"):
        if not directory:
            continue
        path = os.path.join(directory, name)
        if readable_file(path):
            if directory.startswith("."):
                out("Found file(REL): ./%s" % name)
            else:
                out("Found file(lib): %s" % path)
            return path
    return None


class HalRunner:
    """Runs the HAL parts of a configuration with the right halcmd/haltcl invocation."""

    def __init__(self, config, tree, env, children, keep_going):
        """config: Config; env: exported environment; children: Children; keep_going: -k."""
        self.config, self.tree, self.env = config, tree, env
        self.children, self.keep_going = children, keep_going

    def halcmd(self):
        """halcmd as $HALCMD says (with -k when -k was given)."""
        return self.env["HALCMD"].split()

    def failed(self, what, num, status):
        """Report a failed HAL step; raises unless -k."""
        err = self.config.error("HAL", what[0], "%s failed (exit status %d)" % (what[1], status),
                                num)
        if not self.keep_going:
            raise err
        sys.stderr.write("%s (continuing: -k)\n" % err)

    def halfile(self, num, value):
        """Resolve and run the num-th (1-based) HALFILE entry."""
        name, args = split_value(value)
        path = resolve(name, self.tree.hallib, self.env["HALLIB_PATH"])
        if path is None or os.path.isdir(path or ""):
            out("CANNOT FIND FILE FOR:%s" % name)
            raise self.config.error("HAL", "HALFILE", "'%s' not found (searched %s)"
                                    % (name, self.env["HALLIB_PATH"]), num)
        if path.endswith(".tcl"):
            argv = ["haltcl", "-i", self.config.path, path] + args
        else:
            argv = self.halcmd() + ["-i", self.config.path, "-f", path]
        status = self.children.run(argv)
        if status != 0:
            self.failed(("HALFILE", "HAL file %s" % path), num, status)

    def halfiles(self):
        """Every HALFILE in order, or all of them in two passes when [HAL]TWOPASS is set."""
        if self.config.twopass.strip():
            return self.twopass()
        for num, value in enumerate(self.config.halfiles, 1):
            self.halfile(num, value)

    def twopass(self):
        """Run the HALFILEs through twopass.tcl (merged loadrt, then everything else)."""
        script = os.path.join(self.tree.tcl, "twopass.tcl")
        status = self.children.run(["haltcl", "-i", self.config.path, script])
        if status != 0:
            self.failed(("TWOPASS", "two-pass loading of the HAL files"), 1, status)

    def halcmds(self):
        """Each [HAL]HALCMD value as one halcmd command line."""
        for num, value in enumerate(self.config.halcmds, 1):
            status = self.children.run(self.halcmd() + value.split())
            if status != 0:
                self.failed(("HALCMD", "HAL command '%s'" % value), num, status)

    def shutdown_file(self):
        """[HAL]SHUTDOWN run with halcmd -f during cleanup (errors reported, never fatal)."""
        value = self.config.shutdown
        if not value:
            return
        path = os.path.expanduser(value.split()[0])
        status = self.children.run(["halcmd", "-f", path])
        if status != 0:
            sys.stderr.write("%s: error: [HAL]SHUTDOWN %s failed (exit status %d)%s\n"
                             % (self.config.path, path, status,
                                self.config.where("HAL", "SHUTDOWN")))
