"""logs: without a terminal (and without -r) the session's output goes to temporary log files,
which are kept as ~/linuxcnc_print.txt and ~/linuxcnc_debug.txt when the launch fails."""
import os
import shutil
import sys
import tempfile


def write_atomically(src, dest):
    """Copy src to dest through a temporary file and a rename."""
    tmp = "%s.tmp%d" % (dest, os.getpid())
    shutil.copyfile(src, tmp)
    os.replace(tmp, dest)


class Logs:
    """Where stdout (print file) and stderr (debug file) of the session go."""

    def __init__(self, redirect):
        """redirect: send fd 1 and 2 (inherited by every child) to temporary files."""
        self.redirect = redirect
        self.print_file = self.debug_file = None
        self.saved_stderr = None
        if redirect:
            self._redirect()

    def _redirect(self):
        """Point fd 1 and 2 at fresh temporary files, keeping the original stderr."""
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved_stderr = os.dup(2)
        os.set_inheritable(self.saved_stderr, False)
        for fd, attr in ((1, "print_file"), (2, "debug_file")):
            handle, path = tempfile.mkstemp(prefix="linuxcnc.%s." % attr.split("_")[0])
            os.dup2(handle, fd)
            os.close(handle)
            setattr(self, attr, path)

    def tell(self, text):
        """A line for the operator even while output is redirected."""
        if self.saved_stderr is not None:
            os.write(self.saved_stderr, (text + "\n").encode())
        else:
            sys.stderr.write(text + "\n")
            sys.stderr.flush()

    def finish(self, status):
        """Keep the logs in $HOME when the launch failed; remove the temporary files."""
        if not self.redirect:
            return
        sys.stdout.flush()
        sys.stderr.flush()
        if status != 0:
            home = os.path.expanduser("~")
            kept = []
            for src, name in ((self.print_file, "linuxcnc_print.txt"),
                              (self.debug_file, "linuxcnc_debug.txt")):
                try:
                    write_atomically(src, os.path.join(home, name))
                    kept.append(os.path.join(home, name))
                except OSError as e:
                    self.tell("linuxcnc: cannot keep log %s: %s" % (name, e.strerror))
            self.tell("linuxcnc: the launch failed (exit status %d); its output is in %s"
                      % (status, " and ".join(kept)))
        for path in (self.print_file, self.debug_file):
            try:
                os.unlink(path)
            except OSError:
                pass
