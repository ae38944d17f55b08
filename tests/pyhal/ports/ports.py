"""ports.py: writes and reads bytes through a port signal between two Python port pins."""
import subprocess

import hal
from pyhal_test import show


c = hal.component("pyport")
tx = c.newpin("tx", hal.HAL_PORT, hal.HAL_OUT)
rx = c.newpin("rx", hal.HAL_PORT, hal.HAL_IN)
c.ready()
show("unlinked write", lambda: tx.write(b"x"))
subprocess.run(["halcmd", "net", "bytes", "pyport.tx", "pyport.rx"], check=True)
subprocess.run(["halcmd", "sets", "bytes", "16"], check=True)
show("sizes", lambda: (tx.size(), rx.size(), c.tx, hal.get_s("bytes")))
show("write hello", lambda: tx.write(b"hello"))
show("write str", lambda: tx.write(" world"))
show("write too much", lambda: tx.write(b"0123456789"))
show("readable", lambda: (c.getitem("rx").readable(), c.getitem("tx").writable()))
show("peek 2", lambda: rx.peek(2))
show("peek_commit 2", lambda: rx.peek_commit(2))
show("read 9", lambda: rx.read(9))
show("read 1 empty", lambda: rx.read(1))
show("write on input", lambda: rx.write(b"x"))
show("read on output", lambda: tx.read(1))
tx.write(b"abc")
rx.clear()
show("after clear", lambda: c.getitem("rx").readable())
