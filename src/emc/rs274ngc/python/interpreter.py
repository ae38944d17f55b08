"""interpreter: the running RS274NGC interpreter as remap, O-word and namedparams code sees it.

Loaded by the interpreter's embedded Python (never imported from disk by name): `this` is the
interpreter, passed as `self` to every remap, O-word and namedparams function.
"""
from collections.abc import Mapping

import _rs274ngc as _state

INTERP_OK = 0
INTERP_EXIT = 1
INTERP_EXECUTE_FINISH = 2
INTERP_ENDFILE = 3
INTERP_FILE_NOT_OPEN = 4
INTERP_ERROR = 5
INTERP_MIN_ERROR = 3

TOLERANCE_INCH = 0.0002
TOLERANCE_MM = 0.002
TOLERANCE_CONCAVE_CORNER = 0.05
TOLERANCE_EQUAL = 0.0001

UNITS_PER_MINUTE = 0
INVERSE_TIME = 1
UNITS_PER_REVOLUTION = 2
MODE_ABSOLUTE = 0
MODE_INCREMENTAL = 1
R_PLANE = 0
OLD_Z = 1
OFF = 0
LEFT = 1
RIGHT = 2
CANON_PLANE_XY, CANON_PLANE_YZ, CANON_PLANE_XZ = 1, 2, 3
CANON_PLANE_UV, CANON_PLANE_VW, CANON_PLANE_UW = 4, 5, 6
CANON_UNITS_INCHES, CANON_UNITS_MM, CANON_UNITS_CM = 1, 2, 3

# Named parameter attribute bits (sub_context[n].named_params[name].attr).
PA_READONLY = 1
PA_GLOBAL = 2
PA_UNSET = 4
PA_USE_LOOKUP = 8
PA_FROM_INI = 16
PA_PYTHON = 32

# When nonzero, self.execute() raises InterpreterException instead of returning an error code.
throw_exceptions = 1


class InterpreterException(Exception):
    """An error of self.execute(): where it happened and the interpreter's message."""

    def __init__(self, line_number, line_text, error_message):
        Exception.__init__(self, error_message)
        self.line_number = line_number
        self.line_text = line_text
        self.error_message = error_message


def equal(a, b):
    """True when a and b differ by less than TOLERANCE_EQUAL (the interpreter's comparison)."""
    return abs(a - b) < TOLERANCE_EQUAL


class Params:
    """self.params: numbered (int key) and named (str key) parameters; names without a leading
    underscore are local to the current call level."""

    def __getitem__(self, key):
        return _state.param_get(key)

    def __setitem__(self, key, value):
        _state.param_set(key, float(value))

    def __contains__(self, key):
        try:
            _state.param_get(key)
        except (KeyError, IndexError):
            return False
        return True

    def __call__(self):
        return self.locals() + self.globals()

    def __len__(self):
        return len(self.locals()) + len(self.globals())

    def locals(self):
        return _state.param_names("locals")

    def globals(self):
        return _state.param_names("globals")


class ParamEntry:
    """One named parameter of a call level: value and PA_* attribute bits."""

    def __init__(self, name, attr, value):
        self._name = name
        self.attr = attr
        self._value = value

    @property
    def value(self):
        return _state.param_get(self._name) if self._value is None else self._value


class NamedParamItem:
    """What iterating named_params yields: key() and data()."""

    def __init__(self, name, entry):
        self._name = name
        self._entry = entry

    def key(self):
        return self._name

    def data(self):
        return self._entry


class NamedParams(Mapping):
    """The named parameters of one call level (level 0 also holds the globals)."""

    def __init__(self, table):
        self._entries = {n: ParamEntry(n, a, v) for n, (a, v) in table.items()}

    def __getitem__(self, name):
        return self._entries[name]

    def __len__(self):
        return len(self._entries)

    def __iter__(self):
        return (NamedParamItem(n, self._entries[n]) for n in sorted(self._entries))

    def keys(self):
        return sorted(self._entries)


class Remap:
    """A REMAP= definition: name, argspec, modal_group, motion_code, prolog_func, remap_py,
    remap_ngc, epilog_func."""

    def __init__(self, fields):
        self.__dict__.update(fields)

    def __repr__(self):
        return "<Remap %s>" % self.name


class Block:
    """A block (line) as the interpreter parsed it: x_flag/x_number per word, g_modes, m_modes,
    comment, o_name, params (O-call arguments), executing_remap."""

    def __init__(self, fields):
        remap = fields.pop("executing_remap")
        self.__dict__.update(fields)
        self.executing_remap = Remap(remap) if remap is not None else None


class _Levels:
    """A read-only sequence built on count/get functions of the state module."""

    def __init__(self, count, get):
        self._count = count
        self._get = get

    def __len__(self):
        return self._count()

    def __getitem__(self, index):
        n = self._count()
        if index < 0:
            index += n
        if not 0 <= index < n:
            raise IndexError("index out of range")
        return self._get(index)

    def __iter__(self):
        return (self[i] for i in range(self._count()))


class Context:
    """One call level: subname, filename, sequence_number, position, saved_params, named_params."""

    def __init__(self, fields):
        named = fields.pop("named_params")
        self.__dict__.update(fields)
        self.named_params = NamedParams(named)


class Pose:
    """Nine axis values x y z a b c u v w."""

    _AXES = "xyzabcuvw"

    def __init__(self, values):
        for axis, v in zip(self._AXES, values):
            setattr(self, axis, v)

    def __iter__(self):
        return (getattr(self, a) for a in self._AXES)

    def __repr__(self):
        return "Pose(%s)" % ", ".join("%s=%g" % (a, getattr(self, a)) for a in self._AXES)


class _ToolOffset:
    """tool_table[n].offset: reads and writes the row's offset."""

    def __init__(self, index):
        object.__setattr__(self, "_index", index)

    def __getattr__(self, axis):
        if len(axis) != 1 or axis not in Pose._AXES:
            raise AttributeError(axis)
        return _state.tool(self._index)[2][Pose._AXES.index(axis)]

    def __setattr__(self, axis, value):
        if len(axis) != 1 or axis not in Pose._AXES:
            raise AttributeError(axis)
        _state.tool_set(self._index, axis, float(value))


class ToolEntry:
    """One tool-table row (index 0 is the spindle): toolno, pocketno, offset, diameter,
    frontangle, backangle, orientation."""

    _FIELDS = ("toolno", "pocketno", "offset", "diameter", "frontangle", "backangle", "orientation")

    def __init__(self, index):
        object.__setattr__(self, "_index", index)

    def __getattr__(self, name):
        if name not in self._FIELDS:
            raise AttributeError(name)
        if name == "offset":
            return _ToolOffset(self._index)
        return _state.tool(self._index)[self._FIELDS.index(name)]

    def __setattr__(self, name, value):
        if name not in self._FIELDS or name == "offset":
            raise AttributeError("cannot set tool field '%s'" % name)
        _state.tool_set(self._index, name, float(value))

    def __repr__(self):
        t = _state.tool(self._index)
        return "<tool %d pocket %d offset %s diameter %g>" % (t[0], t[1], t[2], t[3])


class _Speeds:
    """self.speed: the programmed speed of each spindle, readable and writable by index."""

    def __len__(self):
        return len(_state.get("speed"))

    def __getitem__(self, index):
        return _state.get("speed")[index]

    def __setitem__(self, index, value):
        _state.set_speed(index, float(value))

    def __iter__(self):
        return iter(_state.get("speed"))

    def __repr__(self):
        return repr(_state.get("speed"))


_STATE_NAMES = frozenset(_state.names()) - {"speed"}
_PARAMS = Params()


class Interp:
    """The interpreter. Attributes not listed here come from the interpreter state
    (feed_rate, current_x, call_level, remap_level, ...); any other attribute set on it is kept."""

    @property
    def params(self):
        return _PARAMS

    @property
    def blocks(self):
        return _Levels(_state.block_count, lambda i: Block(_state.block(i)))

    @property
    def sub_context(self):
        return _Levels(_state.context_count, lambda i: Context(_state.context(i)))

    @property
    def tool_table(self):
        return _Levels(_state.tool_count, ToolEntry)

    @property
    def speed(self):
        return _Speeds()

    @property
    def tool_offset(self):
        return Pose([_state.get("tool_offset_" + a) for a in Pose._AXES])

    @property
    def remaps(self):
        return {k: Remap(v) for k, v in _state.remaps().items()}

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return _state.get(name)

    def __setattr__(self, name, value):
        if name in _STATE_NAMES:
            _state.set(name, value)
        else:
            object.__setattr__(self, name, value)

    def __dir__(self):
        return sorted(set(object.__dir__(self)) | _STATE_NAMES)

    def execute(self, code, lineno=None):
        """Run one line of G-code now (and any procedure it calls); returns INTERP_OK or, with
        throw_exceptions off, the error code. Raises InterpreterException on errors."""
        status, message = _state.execute(code)
        if status >= INTERP_MIN_ERROR and throw_exceptions:
            line = lineno if lineno is not None else self.sequence_number
            raise InterpreterException(line, code, message)
        return status

    def set_errormsg(self, message):
        """The message an INTERP_ERROR return reports."""
        _state.set_errormsg(str(message))

    def get_errormsg(self):
        return _state.get_errormsg()

    def find_tool_pocket(self, toolno):
        """(INTERP_OK, tool-data index) of a tool number (T0, no tool, is index 0),
        (INTERP_ERROR, -1) when it is not there."""
        index = 0 if int(toolno) == 0 else _state.find_tool(int(toolno))
        return (INTERP_OK, index) if index >= 0 else (INTERP_ERROR, -1)

    def set_tool_parameters(self):
        """Make tool_table[current_pocket] the loaded tool (tool_table[0], #5400-#5413)."""
        return _state.set_tool_parameters()


this = Interp()
