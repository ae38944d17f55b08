"""handshake.py: RasterProgrammer.start() returns once raster runs the program, so a position set
right after start() is already the first position of the line; stop() returns once raster left it,
so back-to-back programs never blend into one."""
import subprocess
import raster
from pyhal import component, halType, pinDir


def halcmd(*args):
    subprocess.run(["halcmd"] + list(args), check=True)


def getp(name):
    return subprocess.run(["halcmd", "getp", name], check=True, capture_output=True,
                          text=True).stdout.strip()


axis = component("axis")
position = axis.pinNew("position", halType.FLOAT, pinDir.OUT)
axis.ready()
prog = raster.RasterProgrammer("prog")
for pin, sig in (("prog.program", "program"), ("raster.0.program", "program"),
                 ("prog.run", "run"), ("raster.0.run", "run"),
                 ("raster.0.enabled", "enabled"), ("prog.enabled", "enabled"),
                 ("raster.0.fault-code", "code"), ("prog.fault-code", "code"),
                 ("axis.position", "pos"), ("raster.0.position", "pos")):
    halcmd("net", sig, pin)
halcmd("sets", "program", "256")

for start, offset, after in ((-1.0, 1.0, -0.5), (2.0, -1.0, 1.5), (5.0, 0.5, 9.0)):
    position.value = start
    prog.begin(offset, 4, 1.0, 2)
    prog.data("0E")
    running = prog.start()
    position.value = after          # the axis moves on at once
    print("start at %.1f offset %.1f: running %s, program-position %s" %
          (start, offset, running, getp("raster.0.program-position")))
    print("  stopped: %s, enabled %s" % (prog.stop(), getp("raster.0.enabled")))

prog.begin(1.0, 3, 1.0, 2)          # 3 bits per pixel: raster faults (invalid bpp)
prog.data("0E")
print("bad program: running %s, fault %r" % (prog.start(), prog.fault()))
prog.exit()
axis.exit()
