"""nmlfile: the shared-memory buffers an .nml file declares (for readiness and cleanup)."""
from .errors import LaunchError

KEY_COLUMN = 9     # B name type host size neut rpc# buffer# max_procs key [options]


def shmem_buffers(path):
    """[(name, key, line)] of the 'B ... SHMEM ...' lines of an NML file."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
    except OSError as e:
        raise LaunchError("%s: error: cannot read the NML file: %s" % (path, e.strerror))
    found = []
    for number, line in enumerate(lines, 1):
        col = line.split("#", 1)[0].split()
        if len(col) > KEY_COLUMN and col[0] == "B" and col[2] == "SHMEM":
            try:
                found.append((col[1], int(col[KEY_COLUMN], 0), number))
            except ValueError:
                raise LaunchError("%s:%d: error: buffer %s: key '%s' is not a number"
                                  % (path, number, col[1], col[KEY_COLUMN]))
    return found
