"""raster: send raster programs to the `raster` component through its program port.

    prog = RasterProgrammer("programmer")   # pins programmer.program (port out), .run (bit out),
                                            # .enabled (bit in), .fault-code (s32 in)
    prog.begin(offset, bpp, ppu, count)     # header "offset;bpp;ppu;count;"
    prog.data("0E")                         # count*bpp/4 hex digits
    prog.start()                            # run = TRUE, waits until enabled (or a fault)
    prog.stop()                             # run = FALSE, waits until enabled falls
    prog.exit()

The program format and the fault codes are the raster component's (see its man page).
"""
import enum
import time

from pyhal import component, halType, pinDir

__all__ = ["FaultCodes", "RasterProgrammer"]

# How long to wait for room in the port before giving up, in seconds.
SEND_TIMEOUT = 5.0
# How long start() and stop() wait for the component to answer on its enabled pin, in seconds
# (an unwired enabled pin costs this much once per call).
HANDSHAKE_TIMEOUT = 0.25


class FaultCodes(enum.IntEnum):
    """Values of the raster component's fault-code pin."""
    NoFault = 0
    InvalidOffset = 1
    InvalidBPP = 2
    InvalidPPU = 3
    InvalidCount = 4
    InvalidPixelData = 5
    ProgramSizeMismatch = 6


class RasterProgrammer:
    """A HAL component that writes raster programs into a port and starts and stops them."""

    def __init__(self, name):
        self.comp = component(name)
        self.port = self.comp.pinNew("program", halType.PORT, pinDir.OUT)
        self.run = self.comp.pinNew("run", halType.BIT, pinDir.OUT)
        self.enabled = self.comp.pinNew("enabled", halType.BIT, pinDir.IN)
        self.fault_code = self.comp.pinNew("fault-code", halType.SIGNED, pinDir.IN)
        self.comp.ready()

    def _send(self, text):
        """Write text into the port, in pieces as room frees up; TimeoutError when it stays full."""
        data = text.encode() if isinstance(text, str) else bytes(text)
        deadline = time.monotonic() + SEND_TIMEOUT
        while data:
            room = self.port.writable()
            if room:
                piece = data[:room]
                if self.port.write(piece):
                    data = data[len(piece):]
                    continue
            if time.monotonic() > deadline:
                raise TimeoutError("raster program port %s stays full" % self.port.name)
            time.sleep(0.001)

    def begin(self, offset, bpp, ppu, count):
        """Send the header of a program: offset;bpp;ppu;count;"""
        self._send("%s;%d;%s;%d;" % (repr(float(offset)), int(bpp), repr(float(ppu)), int(count)))

    def data(self, pixels):
        """Send pixel data: bpp/4 hex digits per pixel."""
        self._send(pixels)

    def start(self, timeout=HANDSHAKE_TIMEOUT):
        """Set run and wait until the raster component runs the program (enabled) or faults, so
        the axis position it starts from is the one set before start(). True when running."""
        self.run.value = True
        return self._await(lambda: self.enabled.value or self.fault_code.value != 0, timeout) and \
            bool(self.enabled.value)

    def stop(self, timeout=HANDSHAKE_TIMEOUT):
        """Clear run and wait until the component has left the program (enabled falls), so the
        next program cannot be mistaken for the rest of this one. True when it has."""
        self.run.value = False
        return self._await(lambda: not self.enabled.value, timeout)

    @staticmethod
    def _await(condition, timeout):
        """Poll condition every millisecond for up to timeout seconds; its last answer."""
        deadline = time.monotonic() + timeout
        while not condition():
            if time.monotonic() > deadline:
                return False
            time.sleep(0.001)
        return True

    def fault(self):
        """The component's fault code as a FaultCodes member (unknown values as int)."""
        code = self.fault_code.value
        try:
            return FaultCodes(code)
        except ValueError:
            return code

    def exit(self):
        self.comp.exit()
