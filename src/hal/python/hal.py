"""hal.py: the Python `hal` module: userspace components over the _hal extension."""
import enum
import signal
import sys
import warnings

from _hal import *  # noqa: F401,F403
import _hal

# helpers of _hal used only through the component class below
del init_component, ready, unready, exit_component, new_item  # noqa: F821

HAL_NAME_LEN = 55
_CLOSED = "Invalid operation on closed HAL component"


class Type(enum.IntEnum):
    """HAL value types (python.md §2)."""
    BOOL = 1
    REAL = 2
    S32 = 3
    U32 = 4
    PORT = 5
    SINT = 6
    UINT = 7
    HAL_BOOL = 1
    HAL_REAL = 2
    HAL_S32 = 3
    HAL_U32 = 4
    HAL_PORT = 5
    HAL_SINT = 6
    HAL_UINT = 7


class Dir(enum.IntEnum):
    """Pin and param directions."""
    IN = 16
    OUT = 32
    IO = 48
    RO = 64
    RW = 192
    HAL_IN = 16
    HAL_OUT = 32
    HAL_IO = 48
    HAL_RO = 64
    HAL_RW = 192


class CompType(enum.IntEnum):
    """Component kinds."""
    UNKNOWN = -1
    USER = 0
    REALTIME = 1
    OTHER = 2


class RTType(enum.IntEnum):
    """Realtime environment kinds (rtapi.md §5)."""
    UNINITIALIZED = -1
    NONE = 0
    UNKNOWN = 1
    PREEMPT_DYNAMIC = 2
    PREEMPT_RT = 3
    RTAI = 4
    LXRT = 5
    XENOMAI = 6
    XENOMAI_EVL = 7


for _member in RTType:
    globals()["REALTIME_TYPE_" + _member.name] = int(_member)
del _member


def get_realtime_type():
    """Return the realtime type as an RTType member."""
    return RTType(_hal.get_realtime_type())


def __getattr__(name):
    """Compute the deprecated is_rt / is_sim flags on access."""
    if name in ("is_rt", "is_sim"):
        warnings.warn("%s is deprecated, use lcnc_realtime.verify() instead" % name,
                      FutureWarning, stacklevel=2)
        realtime = _hal.get_realtime_type() > 0
        return realtime if name == "is_rt" else not realtime
    raise AttributeError("module 'hal' has no attribute %r" % name)


class _Item:
    """Common part of Pin and Param: a named pin/param of a component."""

    def __init__(self, comp, item):
        self._comp = comp
        self._item = item

    def _raw(self):
        """The raw item, refusing access after the component exited."""
        self._comp._check_open()
        return self._item

    def get(self):
        """Current value."""
        return self._raw().get()

    def set(self, value):
        """Write a value."""
        return self._raw().set(value)

    def get_type(self):
        """HAL type as int."""
        return self._raw().get_type()

    def get_dir(self):
        """Direction as int."""
        return self._raw().get_dir()

    def get_name(self):
        """Short name (without the component prefix)."""
        return self._raw().get_name()

    def is_pin(self):
        """True for pins."""
        return self._raw().is_pin()

    name = property(get_name)
    type = property(get_type)
    dir = property(get_dir)
    value = property(get, set)


class Pin(_Item):
    """A pin of a Python component; PORT pins also move bytes."""

    def write(self, data):
        """PORT OUT: write bytes or str; True when all of it fit."""
        return self._raw().write(data)

    def read(self, count):
        """PORT IN: read count bytes (bytes), or False when fewer are available."""
        return self._raw().read(count)

    def peek(self, count):
        """PORT IN: look at count bytes without consuming them, or False."""
        return self._raw().peek(count)

    def peek_commit(self, count):
        """PORT IN: consume count bytes looked at with peek."""
        return self._raw().peek_commit(count)

    def clear(self):
        """PORT: drop every byte in the buffer."""
        return self._raw().clear()

    def size(self):
        """PORT: buffer size in bytes."""
        return self._raw().size()


class Param(_Item):
    """A parameter of a Python component."""


class component:
    """A userspace HAL component owned by this Python process."""

    def __init__(self, name, prefix=None):
        self.__dict__["_id"] = _hal.init_component(name)
        self.__dict__["_name"] = name
        self.__dict__["_prefix"] = name if prefix is None else prefix
        self.__dict__["_items"] = {}
        self.__dict__["_open"] = True

    def _check_open(self):
        """Raise RuntimeError once the component has exited."""
        if not self.__dict__["_open"]:
            raise RuntimeError(_CLOSED)

    def _new(self, name, type_, dir_, is_pin):
        """Create a pin or param named prefix.name and wrap it."""
        self._check_open()
        kind = "pin" if is_pin else "param"
        if name in self._items:
            label = "pin" if is_pin else "parameter"
            raise ValueError("Duplicate %s name '%s'" % (label, name))
        type_ = int(type_)
        dir_ = int(dir_)
        valid_types = range(1, 8) if is_pin else (1, 2, 3, 4, 6, 7)
        if type_ not in valid_types:
            raise error("Invalid %s type %d" % (kind, type_))
        valid_dirs = (Dir.IN, Dir.OUT, Dir.IO) if is_pin else (Dir.RO, Dir.RW)
        if dir_ not in valid_dirs:
            raise error("Invalid argument")
        full = "%s.%s" % (self._prefix, name)
        if len(full) > HAL_NAME_LEN:
            raise error('Invalid %s name length "%s": max = %d characters'
                        % (kind, full, HAL_NAME_LEN))
        raw = _hal.new_item(self._id, full, name, type_, dir_, is_pin)
        wrapped = (Pin if is_pin else Param)(self, raw)
        self._items[name] = wrapped
        return wrapped

    def newpin(self, name, type, dir):
        """Create pin prefix.name; returns a Pin."""
        return self._new(name, type, dir, True)

    def newparam(self, name, type, dir):
        """Create param prefix.name; returns a Param."""
        return self._new(name, type, dir, False)

    def _lookup(self, name):
        """The wrapped item of a short name, or AttributeError."""
        self._check_open()
        try:
            return self._items[name]
        except KeyError:
            raise AttributeError("Pin or param '%s' does not exist" % name) from None

    def getpin(self, name):
        """Existing pin by short name."""
        item = self._lookup(name)
        if not item.is_pin():
            raise AttributeError("Pin '%s' does not exist" % name)
        return item

    def getparam(self, name):
        """Existing param by short name."""
        item = self._lookup(name)
        if item.is_pin():
            raise AttributeError("Param '%s' does not exist" % name)
        return item

    def getitem(self, name):
        """The raw hal.item of a short name."""
        return self._lookup(name)._item

    def getpins(self):
        """Dict short name -> value of every pin and param."""
        self._check_open()
        return {name: item.get() for name, item in self._items.items()}

    def ready(self):
        """Mark the component ready."""
        self._check_open()
        _hal.ready(self._id)

    def unready(self):
        """Make the component not ready again so items can be added."""
        self._check_open()
        _hal.unready(self._id)

    def exit(self):
        """Remove the component from HAL."""
        self._check_open()
        self.__dict__["_open"] = False
        _hal.exit_component(self._id)

    def getprefix(self):
        """Prefix used for items created from now on."""
        self._check_open()
        return self._prefix

    def setprefix(self, prefix):
        """Change the prefix for items created from now on."""
        self._check_open()
        self.__dict__["_prefix"] = prefix

    def __getitem__(self, name):
        return self._lookup(name).get()

    def __setitem__(self, name, value):
        self._lookup(name).set(value)

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return self._lookup(name).get()

    def __setattr__(self, name, value):
        if name in type(self).__dict__ or name in self.__dict__:
            object.__setattr__(self, name, value)
        else:
            self._lookup(name).set(value)

    def __len__(self):
        self._check_open()
        return len(self._items)

    def __repr__(self):
        self._check_open()
        return "<hal component %s(%d) with %d pins and params>" % (
            self._name, self._id, len(self._items))

    def __del__(self):
        if self.__dict__.get("_open"):
            self.__dict__["_open"] = False
            try:
                _hal.exit_component(self.__dict__["_id"])
            except Exception:  # interpreter shutdown or HAL already gone
                pass


# `hal.query` and `import hal.query`
import hal_query as query  # noqa: E402
__path__ = []
sys.modules[__name__ + ".query"] = query


def _on_sigterm(signum, frame):
    """SIGTERM (halcmd unload) raises KeyboardInterrupt in the main thread."""
    raise KeyboardInterrupt


signal.signal(signal.SIGTERM, _on_sigterm)
