"""cleanup: stop a session completely: display, applications, task and other user components,
linuxcncsvr, HAL threads and modules, rtapi_app, and every shared-memory segment it owned."""
import os
import signal
import time

from . import children as kids
from . import halstate, instance, sysv

USER_COMP_GRACE_S = 2.0
STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM, signal.SIGHUP}


def stop_user_components(session):
    """SIGTERM every user-space component's process; SIGKILL those still there after a grace.
    Task (the owner of inihal) goes first, alone: it disables motion on its way out, so
    motion (or motion-logger) must still be there, as in LinuxCNC's cleanup order."""
    comps = halstate.user_components(session.children)
    task = sorted({pid for name, pid in comps if name == "inihal" and pid != os.getpid()})
    if task:
        signal_and_wait(session, task, [n for n, p in comps if p in task])
        comps = halstate.user_components(session.children)
    pids = sorted({pid for _, pid in comps if pid != os.getpid()})
    if not pids:
        return
    signal_and_wait(session, pids, [n for n, _ in comps])


def signal_and_wait(session, pids, names):
    """SIGTERM pids, wait up to the grace, SIGKILL the survivors."""
    session.note("stopping user-space components: %s" % ", ".join(names))
    for pid in pids:
        try:
            os.kill(pid, signal.SIGTERM)
        except OSError:
            pass
    deadline = time.monotonic() + USER_COMP_GRACE_S
    while time.monotonic() < deadline and any(kids.alive(p) for p in pids):
        session.children.reap()
        time.sleep(0.02)
    survivors = [p for p in pids if kids.alive(p)]
    if survivors:
        session.tell("linuxcnc: user-space components did not stop on SIGTERM, killing pid %s"
                     % survivors)
        instance.kill_processes(survivors, grace_s=0)
    session.children.reap()


def stop_hal(session):
    """[HAL]SHUTDOWN, user components, linuxcncsvr, threads, realtime modules, rtapi_app."""
    run = session.children.run
    if session.hal_runner is not None:
        session.hal_runner.shutdown_file()
    stop_user_components(session)
    session.children.stop("server")
    run(["halcmd", "stop"])
    run(["halcmd", "unload", "all"])
    run([session.env["REALTIME"], "stop"])


def remove_segments(session):
    """Remove the NML, motion and other segments of the instance nobody holds any more."""
    number = session.lease.number
    extra = [key for _, key, _ in session.nml_buffers] + [session.config.shmem_key]
    left = instance.remove_idle_segments(number, lambda text: None, extra)
    if left:
        session.tell("linuxcnc: shared memory still attached after cleanup in "
                     "OPENEMC_INSTANCE=%d: %s" % (number, ", ".join(
                         "0x%08x (%d attached)" % kv for kv in sorted(left.items()))))


def cleanup(session):
    """Everything the session started is stopped; safe to call at any point of the start-up."""
    signal.pthread_sigmask(signal.SIG_BLOCK, STOP_SIGNALS)
    try:
        session.note("cleaning up")
        session.children.stop("display")
        session.children.stop("splash")
        for name in [n for n in session.children.started if n.startswith("app")]:
            session.children.stop(name)
        if session.realtime_started:
            stop_hal(session)
        else:
            session.children.stop("server")
        session.note("stopping what is left")
        kids.stop_all_descendants(say=session.tell)
        if session.lease is not None:
            remove_segments(session)
            session.lease.release()
        session.note("cleaned up")
    finally:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, STOP_SIGNALS)


def leftover_report(number, extra_bases):
    """Text naming what of an instance is still there (processes or segments), '' if nothing."""
    parts = []
    pids = sysv.rtapi_app_pids(number)
    if pids:
        parts.append("rtapi_app pid %s" % pids)
    segs = sysv.instance_segments(number, extra_bases)
    if segs:
        parts.append("segments %s" % ", ".join("0x%08x" % k for k in sorted(segs)))
    return "; ".join(parts)
