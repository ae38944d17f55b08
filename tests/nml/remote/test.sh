#!/bin/bash
# REMOTE process lines naming this machine (localhost, 127.x.y.z, ::1, its host name)
# reach the local shared memory; a REMOTE line naming another host is refused with the
# file, line and host.
cd "$(dirname "$0")"
pid=$(linuxcncsvr -nml remote.nml --daemon) || exit 1
python3 - <<'PY'
import linuxcnc
linuxcnc.nmlfile = "remote.nml"
try:
    print("error channel through REMOTE localhost:", linuxcnc.error_channel().poll())
except linuxcnc.error as err:
    print("error channel:", err)
PY
python3 - <<'PY' 2>&1 | sed 's|/.*/remote.nml|remote.nml|'
import ctypes, os
lib = ctypes.CDLL(os.path.join(os.environ["EMC2_HOME"], "lib", "libnml.so"))
lib.nml_open.restype = ctypes.c_void_p
err = ctypes.create_string_buffer(512)
for proc in (b"xemc", b"far"):
    ch = lib.nml_open(b"remote.nml", b"emcStatus", proc, err, len(err))
    print(proc.decode(), "opens" if ch else "refused: " + err.value.decode())
PY
kill "$pid"
while kill -0 "$pid" 2>/dev/null; do sleep 0.02; done
