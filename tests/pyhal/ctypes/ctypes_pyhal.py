"""ctypes_pyhal.py: pyhal pins, signals and ports, and raster.RasterProgrammer's port output."""
import subprocess

from pyhal import component, halType, pinDir, HalError
import raster


def show(label, fn):
    """Print label and the result of fn(), or the exception it raised."""
    try:
        value = fn()
    except Exception as e:  # the errors are part of what is tested
        value = "%s: %s" % (type(e).__name__, e)
    print("%s -> %s" % (label, value))


c = component("cty")
pins = {t: (c.pinNew("out-%s" % t.name.lower(), t, pinDir.OUT), c.pinNew("in-%s" % t.name.lower(), t, pinDir.IN))
        for t in (halType.BIT, halType.FLOAT, halType.SIGNED, halType.UNSIGNED, halType.SIGNED64)}
port_out = c.pinNew("port-out", halType.PORT, pinDir.OUT)
port_in = c.pinNew("port-in", halType.PORT, pinDir.IN)
c.ready()
values = {halType.BIT: True, halType.FLOAT: -2.5, halType.SIGNED: -7, halType.UNSIGNED: 4000000000,
          halType.SIGNED64: -(2 ** 40)}
for t, (out, inp) in pins.items():
    c.sigNew("s-%s" % t.name.lower(), t)
    c.sigLink(out.name, "s-%s" % t.name.lower())
    c.sigLink(inp.name, "s-%s" % t.name.lower())
    out.value = values[t]
    show("%s through a signal" % t.name, lambda: inp.value)
show("duplicate pin", lambda: c.pinNew("in-bit", halType.BIT, pinDir.IN))
show("link to a signal of another type", lambda: c.sigLink("cty.in-float", "s-bit"))
show("unknown type", lambda: c.pinNew("odd", 9, pinDir.IN))
c.sigNew("bytes", halType.PORT)
c.sigLink("cty.port-out", "bytes")
c.sigLink("cty.port-in", "bytes")
show("port size before sets", port_in.size)
subprocess.run(["halcmd", "sets", "bytes", "6"], check=True)
show("sizes", lambda: (port_in.size(), port_out.writable(), port_in.readable()))
show("write 'abc'", lambda: port_out.write("abc"))
show("write 3 more (only 2 fit)", lambda: port_out.write(b"xyz"))
show("peek 2", lambda: port_in.peek(2))
show("read 4 of 3", lambda: port_in.read(4))
show("read 3", lambda: port_in.read(3))
show("value of a port pin's type", lambda: port_in.size() - port_in.readable())

prog = raster.RasterProgrammer("rprog")
c.sigNew("program", halType.PORT)
c.sigLink("rprog.program", "program")
reader = component("rread")
rport = reader.pinNew("in", halType.PORT, pinDir.IN)
reader.ready()
reader.sigLink("rread.in", "program")
subprocess.run(["halcmd", "sets", "program", "64"], check=True)
prog.begin(-1.5, 8, 10, 3)
prog.data("00807F")
show("program text", lambda: rport.read(rport.readable()))
prog.start()
show("run", lambda: prog.run.value)
prog.stop()
show("fault code", lambda: repr(prog.fault()))
show("not a port", lambda: prog.run.read(1))
prog.exit()
reader.exit()
c.exit()
show("exit twice", c.exit)
