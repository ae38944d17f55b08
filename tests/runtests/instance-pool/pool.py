"""pool.py: drive scripts/runtests_pool.InstancePool against busy instances and a broken lock dir."""
import ctypes
import os
import socket
import sys
import tempfile

sys.path.insert(0, os.path.join(os.environ["EMC2_HOME"], "scripts"))
import runtests_pool  # noqa: E402

HAL_KEY = 0x48414C32


def make_segment(instance):
    """Create the HAL segment of an instance; return its id."""
    key = HAL_KEY ^ (instance << 24)
    libc = ctypes.CDLL(None, use_errno=True)
    shmid = libc.shmget(ctypes.c_int(key - (1 << 32) if key >= 1 << 31 else key), 4096, 0o1600)
    if shmid < 0:
        sys.exit("shmget failed for instance %d" % instance)
    return shmid


def main():
    """Hold two real instances, make one look used by shm and one by a socket, then pick again."""
    held = runtests_pool.InstancePool(2)
    shm_inst, sock_inst = held.instances
    shmid = make_segment(shm_inst)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    with tempfile.TemporaryDirectory() as work:
        listener.bind("\0%s/.rtapi_fifo.%d" % (work, sock_inst))
        listener.listen(1)
        open(os.path.join(work, runtests_pool.SHARED_LOCKDIR), "w").close()
        tempfile.tempdir = work
        try:
            first = runtests_pool.InstancePool(max(shm_inst, sock_inst))
            second = runtests_pool.InstancePool(1)
        finally:
            tempfile.tempdir = None
            runtests_pool.remove_segment(shmid)
        own = os.path.join(work, "%s-%d" % (runtests_pool.SHARED_LOCKDIR, os.getuid()))
        print("instance with shared memory skipped:", shm_inst not in first.instances)
        print("instance with a listening socket skipped:", sock_inst not in first.instances)
        print("second pool got another instance:", second.instances[0] not in first.instances)
        print("per-user lock files:", len(os.listdir(own)) == len(first.instances) + 1)
    listener.close()


main()
