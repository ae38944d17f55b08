"""pyhal: HAL components, pins, signals and port pins from Python through ctypes over liblinuxcnchal.

    c = component("demo")                  # hal_init
    p = c.pinNew("out", halType.FLOAT, pinDir.OUT)
    c.ready()
    p.value = 1.5
    c.sigNew("sig", halType.FLOAT); c.sigLink("demo.out", "sig")
    port.write("text"); port.read(4) -> b"text" (or "" when that many bytes are not there)
    c.exit()

Errors of the HAL library raise RuntimeError naming the call and the reason.
"""
import ctypes
import enum
import os

__all__ = ["halType", "pinDir", "component", "pin", "HalError"]


class HalError(RuntimeError):
    """A HAL library call failed."""


class halType(enum.IntEnum):
    """HAL value types (hal_type_t)."""
    BIT = 1
    FLOAT = 2
    SIGNED = 3
    UNSIGNED = 4
    PORT = 5
    SIGNED64 = 6
    UNSIGNED64 = 7


class pinDir(enum.IntEnum):
    """Pin directions (hal_pin_dir_t)."""
    IN = 16
    OUT = 32
    IO = 48


def _load_library():
    """liblinuxcnchal.so of this tree (lib/ next to lib/python), else from the loader's path."""
    here = os.path.dirname(os.path.abspath(__file__))
    local = os.path.join(os.path.dirname(here), "liblinuxcnchal.so")
    return ctypes.CDLL(local if os.path.exists(local) else "liblinuxcnchal.so")


_hal = _load_library()
_port_p = ctypes.POINTER(ctypes.c_int)
_SIGNATURES = {
    "hal_init": ([ctypes.c_char_p], ctypes.c_int),
    "hal_ready": ([ctypes.c_int], ctypes.c_int),
    "hal_exit": ([ctypes.c_int], ctypes.c_int),
    "hal_malloc": ([ctypes.c_long], ctypes.c_void_p),
    "hal_pin_new": ([ctypes.c_char_p, ctypes.c_int, ctypes.c_int, ctypes.c_void_p, ctypes.c_int],
                    ctypes.c_int),
    "hal_signal_new": ([ctypes.c_char_p, ctypes.c_int], ctypes.c_int),
    "hal_signal_delete": ([ctypes.c_char_p], ctypes.c_int),
    "hal_link": ([ctypes.c_char_p, ctypes.c_char_p], ctypes.c_int),
    "hal_unlink": ([ctypes.c_char_p], ctypes.c_int),
    "hal_port_read": ([_port_p, ctypes.c_char_p, ctypes.c_uint], ctypes.c_bool),
    "hal_port_peek": ([_port_p, ctypes.c_char_p, ctypes.c_uint], ctypes.c_bool),
    "hal_port_peek_commit": ([_port_p, ctypes.c_uint], ctypes.c_bool),
    "hal_port_write": ([_port_p, ctypes.c_char_p, ctypes.c_uint], ctypes.c_bool),
    "hal_port_readable": ([_port_p], ctypes.c_uint),
    "hal_port_writable": ([_port_p], ctypes.c_uint),
    "hal_port_buffer_size": ([_port_p], ctypes.c_uint),
    "hal_port_clear": ([_port_p], None),
    "hal_port_wait_readable": ([ctypes.POINTER(_port_p), ctypes.c_uint, ctypes.c_void_p], None),
    "hal_port_wait_writable": ([ctypes.POINTER(_port_p), ctypes.c_uint, ctypes.c_void_p], None),
}
for _name, (_args, _res) in _SIGNATURES.items():
    _fn = getattr(_hal, _name)
    _fn.argtypes = _args
    _fn.restype = _res

_CTYPES = {halType.BIT: ctypes.c_bool, halType.FLOAT: ctypes.c_double,
           halType.SIGNED: ctypes.c_int32, halType.UNSIGNED: ctypes.c_uint32,
           halType.PORT: ctypes.c_int, halType.SIGNED64: ctypes.c_int64,
           halType.UNSIGNED64: ctypes.c_uint64}


def _check(result, call):
    """Raise HalError for a negative errno result."""
    if result < 0:
        raise HalError("%s failed: %s" % (call, os.strerror(-result)))
    return result


def _bytes(text):
    """str (UTF-8) or bytes as bytes."""
    return text.encode() if isinstance(text, str) else bytes(text)


class pin:
    """A pin this component owns: `value` reads and writes it; port pins also move bytes."""

    def __init__(self, name, htype, cell):
        self.name = name
        self.type = htype
        self._cell = ctypes.cast(cell, ctypes.POINTER(ctypes.POINTER(_CTYPES[htype])))

    @property
    def value(self):
        return self._cell.contents.contents.value

    @value.setter
    def value(self, v):
        self._cell.contents.contents.value = v

    def _port(self):
        if self.type != halType.PORT:
            raise TypeError("pin %s is not a port" % self.name)
        return ctypes.cast(self._cell.contents, _port_p)

    def size(self):
        """Bytes the port buffer holds (0 before a size is set on its signal)."""
        return _hal.hal_port_buffer_size(self._port()) if self._port().contents.value else 0

    def readable(self):
        return _hal.hal_port_readable(self._port())

    def writable(self):
        return _hal.hal_port_writable(self._port())

    def write(self, data):
        """Write all bytes or none; True when they fit."""
        b = _bytes(data)
        return bool(_hal.hal_port_write(self._port(), b, len(b)))

    def _take(self, count, fn):
        buf = ctypes.create_string_buffer(count)
        return buf.raw[:count] if fn(self._port(), buf, count) else ""

    def read(self, count):
        """count bytes, or "" when fewer are there (nothing is consumed then)."""
        return self._take(count, _hal.hal_port_read)

    def peek(self, count):
        """Like read() without consuming."""
        return self._take(count, _hal.hal_port_peek)

    def peekCommit(self, count):
        return bool(_hal.hal_port_peek_commit(self._port(), count))

    def clear(self):
        _hal.hal_port_clear(self._port())

    def waitReadable(self, count):
        """Sleep until count bytes are readable."""
        _hal.hal_port_wait_readable(ctypes.cast(self._cell, ctypes.POINTER(_port_p)), count, None)

    def waitWritable(self, count):
        """Sleep until count bytes can be written."""
        _hal.hal_port_wait_writable(ctypes.cast(self._cell, ctypes.POINTER(_port_p)), count, None)


class component:
    """A HAL component (hal_init); its pins are named "<component>.<pin>"."""

    def __init__(self, name):
        self.name = name
        self.id = _check(_hal.hal_init(_bytes(name)), "hal_init(%s)" % name)
        self.pins = {}

    def pinNew(self, name, htype, direction):
        """New pin "<component>.<name>"; returns it."""
        htype = halType(htype)
        full = "%s.%s" % (self.name, name)
        cell = _hal.hal_malloc(ctypes.sizeof(ctypes.c_void_p))
        if not cell:
            raise HalError("hal_malloc for pin %s failed: out of HAL memory" % full)
        _check(_hal.hal_pin_new(_bytes(full), int(htype), int(pinDir(direction)), cell, self.id),
               "hal_pin_new(%s)" % full)
        p = pin(full, htype, cell)
        self.pins[name] = p
        return p

    def ready(self):
        _check(_hal.hal_ready(self.id), "hal_ready(%s)" % self.name)

    def exit(self):
        """Remove the component and its pins (once)."""
        if self.id is not None:
            _hal.hal_exit(self.id)
            self.id = None

    def sigNew(self, name, htype):
        _check(_hal.hal_signal_new(_bytes(name), int(halType(htype))), "hal_signal_new(%s)" % name)

    def sigDelete(self, name):
        _check(_hal.hal_signal_delete(_bytes(name)), "hal_signal_delete(%s)" % name)

    def sigLink(self, pin_name, sig_name):
        _check(_hal.hal_link(_bytes(pin_name), _bytes(sig_name)),
               "hal_link(%s, %s)" % (pin_name, sig_name))

    def sigUnlink(self, pin_name):
        _check(_hal.hal_unlink(_bytes(pin_name)), "hal_unlink(%s)" % pin_name)
