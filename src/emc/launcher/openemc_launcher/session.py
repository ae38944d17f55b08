"""session: the start-up sequence of one configuration (ini.md §3) and its end."""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from . import cleanup, display, environment, halstate, inicheck, instance, nmlfile, picker
from .children import Children
from .config import Config, words
from .errors import Interrupted, LaunchError
from .halfiles import HalRunner
from .logs import Logs

SERVER_READY_S = 10.0
TASK_READY_S = 10.0
USR_READY_S = 30.0
POLL_S = 0.05


def on_signal(signum, frame):
    """SIGINT/SIGTERM/SIGHUP: leave the start-up or the display wait and clean up."""
    raise Interrupted(signum)


class Session:
    """One launch: what was started, so cleanup can stop exactly that."""

    def __init__(self, tree, opts):
        """tree: the Tree the launcher runs from; opts: parsed Options."""
        self.tree, self.opts = tree, opts
        self.env = environment.base_environment(tree, opts)
        keep_on_terminal = opts.no_redirect or opts.verbose or opts.debug
        self.logs = Logs(redirect=not keep_on_terminal and not sys.stdin.isatty())
        if self.logs.print_file:
            self.env["PRINT_FILE"] = self.logs.print_file
        self.children = Children(self.env, trace=opts.debug)
        self.config = self.lease = self.hal_runner = None
        self.nml_buffers = []
        self.realtime_started = False
        self.tmpdir = None

    def tell(self, text):
        """A line for the operator (reaches the terminal even when output is logged)."""
        self.logs.tell(text)

    def note(self, text):
        """Progress text shown with -v or -d."""
        if self.opts.verbose or self.opts.debug:
            sys.stderr.write("linuxcnc: [%.3f s] %s\n" % (time.monotonic() - self.children.t0,
                                                           text))
            sys.stderr.flush()

    def report_hal_path(self):
        """-H: print the HAL file search path as each directory is added."""
        dirs = []
        for directory in reversed(self.opts.hal_dirs):
            dirs.insert(0, directory)
            print("HALLIB_PATH = %s" % environment.hallib_path(dirs, self.tree))

    def ini_path(self):
        """Step 2: the absolute INI path (named, last used, or picked); it must exist."""
        name = self.opts.ini
        if name is None:
            name = picker.last_config() if self.opts.last_config else picker.pick(self.tree)
        path = os.path.abspath(os.path.expanduser(name))
        if not os.path.isfile(path):
            raise LaunchError("linuxcnc: cannot find INI file '%s'" % name)
        return path

    def check_programs(self):
        """Stop before anything starts when task, halui or the display cannot be found."""
        for section, key, value in (("TASK", "TASK", self.config.task),
                                    ("HAL", "HALUI", self.config.halui),
                                    ("HAL", "HALBRIDGE", self.config.halbridge)):
            if value and not display.find_program(words(value)[0], self.env,
                                                  self.config.directory, False):
                raise self.config.error(section, key, "program '%s' not found"
                                        % words(value)[0])
        server = self.tree.program("linuxcncsvr")
        if not display.find_program(server, self.env, self.config.directory, False):
            raise LaunchError("linuxcnc: the NML server 'linuxcncsvr' is not installed")
        self.display_argv = display.display_argv(self.config, self.opts, self.env)

    def prepare(self):
        """Steps 1-6: environment, INI check, configuration values, instance, INI directory."""
        self.report_hal_path()
        path = self.ini_path()
        print("Machine configuration directory is '%s'" % os.path.dirname(path))
        print("Machine configuration file is '%s'" % os.path.basename(path))
        self.config = Config(path, self.tree, self.opts)
        self.config.require()
        if not inicheck.check(self.config.ini, path):
            raise LaunchError("linuxcnc_check_ini validation failed")
        environment.config_environment(self.env, self.config)
        self.nml_buffers = nmlfile.shmem_buffers(self.config.nml_file)
        self.check_programs()
        self.lease = instance.acquire(os.environ, self.tell)
        self.lease.record(path)
        self.env["OPENEMC_INSTANCE"] = str(self.lease.number)
        self.env[instance.SESSION_VAR] = str(os.getpid())
        if "OPENEMC_INSTANCE" not in os.environ:
            self.tell("linuxcnc: running in OPENEMC_INSTANCE=%d (export OPENEMC_INSTANCE=%d to "
                      "reach it with halcmd or Python)" % (self.lease.number, self.lease.number))
        os.chdir(self.config.directory)
        display.start_splash(self.config, self.env, self.children)

    def start_server(self):
        """Step 7: linuxcncsvr creates the NML buffers and tool data; it writes its ready file
        (--ready-file) once they all exist."""
        server = self.tree.program("linuxcncsvr")
        ready = os.path.join(self.private_dir(), "linuxcncsvr.ready")
        proc = self.children.start("server", [server, "-ini", self.config.path,
                                              "--ready-file", ready])
        deadline = time.monotonic() + SERVER_READY_S
        while not os.path.exists(ready):
            if proc.poll() is not None:
                raise LaunchError("linuxcnc: linuxcncsvr exited (status %d) before creating the "
                                  "NML buffers of %s" % (proc.returncode, self.config.nml_file))
            if time.monotonic() > deadline:
                raise LaunchError("linuxcnc: linuxcncsvr did not create the NML buffers of %s "
                                  "within %.0f s" % (self.config.nml_file, SERVER_READY_S))
            time.sleep(POLL_S / 5)

    def private_dir(self):
        """A temporary directory of this session (removed at the end)."""
        if self.tmpdir is None:
            self.tmpdir = tempfile.mkdtemp(prefix="linuxcnc.")
        return self.tmpdir

    def start_realtime(self):
        """Steps 8-9: rtapi_app, then the planner and homing modules."""
        self.realtime_started = True
        if self.children.run([self.env["REALTIME"], "start"]) != 0:
            raise LaunchError("linuxcnc: realtime start failed (see the messages above)")
        for value, section, key in ((self.config.tpmod, "TRAJ", "TPMOD"),
                                    (self.config.homemod, "EMCMOT", "HOMEMOD")):
            if self.children.run(["halcmd", "loadrt"] + value.split()) != 0:
                raise self.config.error(section, key, "loading module '%s' failed" % value)

    def start_usr(self, comp, value, section, key):
        """Steps 10-11: a user program started with halcmd loadusr -Wn COMP PROG ARGS -ini INI."""
        argv = ["halcmd", "loadusr", "-Wn", comp] + words(value) + ["-ini", self.config.path]
        try:
            status = self.children.run(argv, timeout=USR_READY_S)
        except subprocess.TimeoutExpired:
            raise self.config.error(section, key, "'%s' did not make HAL component '%s' ready "
                                    "within %.0f s" % (value, comp, USR_READY_S))
        if status != 0:
            raise self.config.error(section, key, "'%s' did not become ready (HAL component "
                                    "'%s')" % (value, comp))

    def wait_task_ready(self):
        """Step 16: wait until task published [TRAJ] settings (ini.traj_max_velocity non-zero)."""
        deadline = time.monotonic() + TASK_READY_S
        while time.monotonic() < deadline:
            value = halstate.value(self.children, "ini.traj_max_velocity")
            if halstate.nonzero(value):
                return
            if value is None and "inihal" not in halstate.component_names(self.children):
                raise LaunchError("linuxcnc: task (%s) exited during start-up"
                                  % self.config.task)
            self.children.reap()
            time.sleep(POLL_S)
        self.tell("linuxcnc: warning: task did not report ready within %.0f s "
                  "(ini.traj_max_velocity is still 0); starting the display anyway"
                  % TASK_READY_S)

    def start(self):
        """Steps 7-16: server, realtime, task, halui, HAL files, HALCMD, threads, applications."""
        self.note("starting linuxcncsvr")
        self.start_server()
        self.note("starting realtime")
        self.start_realtime()
        self.note("starting task: %s" % self.config.task)
        self.start_usr("inihal", self.config.task, "TASK", "TASK")
        if self.config.halui:
            self.start_usr("halui", self.config.halui, "HAL", "HALUI")
        if self.config.halbridge:
            self.start_usr("bridge", self.config.halbridge, "HAL", "HALBRIDGE")
        self.hal_runner = HalRunner(self.config, self.tree, self.env, self.children,
                                    self.opts.keep_going)
        self.hal_runner.halfiles()
        self.hal_runner.halcmds()
        if self.children.run(["halcmd", "start"]) != 0:
            raise LaunchError("linuxcnc: halcmd start failed")
        display.start_applications(self.config, self.env, self.children, self.tell)
        self.wait_task_ready()

    def run(self):
        """The whole launch; returns the exit status (the display's, or 1 on a failed start)."""
        status = 1
        handlers = {s: signal.signal(s, on_signal) for s in cleanup.STOP_SIGNALS}
        try:
            self.prepare()
            self.start()
            self.note("running the display")
            status = display.run_display(self.display_argv, self.children, self.tell)
        except Interrupted as e:
            self.note("stopping on signal %d" % e.signum)
            status = 0
        except LaunchError as e:
            if str(e):
                sys.stderr.write("%s\n" % e)
                sys.stderr.flush()
            status = e.status
        finally:
            cleanup.cleanup(self)
            if self.tmpdir:
                shutil.rmtree(self.tmpdir, ignore_errors=True)
            for sig, handler in handlers.items():
                signal.signal(sig, handler)
        self.logs.finish(status)
        return status
