"""children: the processes a launch starts, and finding every descendant so none is left behind.

The launcher makes itself a child subreaper: programs that halcmd starts (task, halui, loadusr
components) are re-parented to the launcher when halcmd exits, so at cleanup every process of
the session is a descendant of the launcher and can be stopped by pid, never by name.
"""
import ctypes
import os
import signal
import subprocess
import sys
import time

PR_SET_CHILD_SUBREAPER = 36


def become_subreaper():
    """Ask the kernel to re-parent orphaned descendants to this process."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)


def parent_map():
    """pid -> parent pid of every process."""
    parents = {}
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % name) as f:
                stat = f.read()
        except OSError:
            continue
        fields = stat[stat.rfind(")") + 2:].split()
        if len(fields) > 1 and fields[0] != "Z":
            parents[int(name)] = int(fields[1])
    return parents


def descendants(root=None):
    """Live (non-zombie) descendants of root (default: this process)."""
    root = os.getpid() if root is None else root
    parents = parent_map()
    found, frontier = [], [root]
    while frontier:
        pid = frontier.pop()
        kids = [p for p, pp in parents.items() if pp == pid]
        found.extend(kids)
        frontier.extend(kids)
    return found


def zombie_children():
    """Children of this process that have exited and wait to be collected."""
    me, found = os.getpid(), []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % name) as f:
                stat = f.read()
        except OSError:
            continue
        fields = stat[stat.rfind(")") + 2:].split()
        if len(fields) > 1 and fields[0] == "Z" and int(fields[1]) == me:
            found.append(int(name))
    return found


def alive(pid):
    """True while pid exists and is not a zombie."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            stat = f.read()
    except OSError:
        return False
    return stat[stat.rfind(")") + 2:][:1] != "Z"


class Children:
    """Starts programs for the launch, traces them with -d, and reaps orphans."""

    def __init__(self, env, trace=False):
        """env: the environment programs get; trace: print every command (-d)."""
        self.env, self.trace = env, trace
        self.started = {}
        self.t0 = time.monotonic()
        become_subreaper()

    def show(self, argv):
        """Print a command before running it when tracing."""
        if self.trace:
            sys.stderr.write("+ [%.3f s] %s\n" % (time.monotonic() - self.t0, " ".join(argv)))
            sys.stderr.flush()

    def run(self, argv, **kw):
        """Run a program to completion; returns its exit status (127 when it cannot run)."""
        self.show(argv)
        try:
            return subprocess.run(argv, env=self.env, **kw).returncode
        except OSError as e:
            sys.stderr.write("linuxcnc: cannot run %s: %s\n" % (argv[0], e.strerror))
            return 127

    def output(self, argv):
        """Run a program and return (status, stdout text); stderr is discarded."""
        try:
            proc = subprocess.run(argv, env=self.env, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, text=True, errors="replace")
        except OSError:
            return 127, ""
        return proc.returncode, proc.stdout

    def start(self, name, argv, **kw):
        """Start a program in the background under a name; returns its Popen."""
        self.show(argv)
        proc = subprocess.Popen(argv, env=self.env, **kw)
        self.started[name] = proc
        return proc

    def reap(self):
        """Collect exited orphans (re-parented to us) that are not one of our own Popen children."""
        own = {p.pid for p in self.started.values()}
        for pid in zombie_children():
            if pid not in own:
                try:
                    os.waitpid(pid, os.WNOHANG)
                except ChildProcessError:
                    pass

    def stop(self, name, grace_s=2.0):
        """SIGTERM a started program, SIGKILL it after grace_s; wait for it."""
        proc = self.started.get(name)
        if proc is None or proc.poll() is not None:
            return
        stop_process(proc, grace_s)


def stop_process(proc, grace_s):
    """SIGTERM a Popen, then SIGKILL after grace_s; waits for it."""
    for sig, wait in ((signal.SIGTERM, grace_s), (signal.SIGKILL, 2.0)):
        try:
            proc.send_signal(sig)
        except OSError:
            return
        try:
            proc.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            continue


def stop_all_descendants(grace_s=2.0, say=None):
    """SIGTERM every remaining descendant, SIGKILL survivors after grace_s; reap them."""
    for sig, wait in ((signal.SIGTERM, grace_s), (signal.SIGKILL, 1.0)):
        pids = descendants()
        if not pids:
            reap_any()
            return
        if say and sig == signal.SIGKILL:
            say("linuxcnc: killing processes that ignored SIGTERM: %s" % pids)
        for pid in pids:
            try:
                os.kill(pid, sig)
            except OSError:
                pass
        deadline = time.monotonic() + wait
        while time.monotonic() < deadline and any(alive(p) for p in pids):
            reap_any()
            time.sleep(0.05)
        reap_any()


def reap_any():
    """Collect every exited child (used once all Popen children have been waited for)."""
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
