"""Data model of a parsed .comp file and the HAL/C name mapping rules."""

import os
import re

# type keyword -> (classic HAL type, uses new-API accessors)
TYPE_MAP = {
    'bit': ('bit', False), 'float': ('float', False), 's32': ('s32', False),
    'u32': ('u32', False), 's64': ('s64', False), 'u64': ('u64', False),
    'port': ('port', False), 'signed': ('s32', False), 'unsigned': ('u32', False),
    'bool': ('bit', True), 'real': ('float', True), 'si32': ('s32', True),
    'ui32': ('u32', True), 'sint': ('s64', True), 'uint': ('u64', True),
}
HAL_DIR = {'in': 'HAL_IN', 'out': 'HAL_OUT', 'io': 'HAL_IO',
           'r': 'HAL_RO', 'rw': 'HAL_RW'}


def to_hal(name):
    """HAL spelling of an item name: '_' -> '-', trailing '-'/'.' dropped."""
    name = name.replace('_', '-').rstrip('-').rstrip('.')
    return re.sub('#+', lambda m: '%%0%dd' % len(m.group(0)), name)


def to_c(name):
    """C identifier of an item name: '#' runs (and separators before) removed."""
    name = re.sub('[-._]*#+', '', name)
    name = name.replace('.', '_').replace('-', '_')
    return re.sub('_+', '_', name)


def hal_prefix_name(comp_name):
    """Instance prefix base: leading 'hal_' stripped, '_' -> '-'."""
    if comp_name.startswith('hal_'):
        comp_name = comp_name[4:]
    return comp_name.replace('_', '-')


class Item:
    """A pin, param, function, variable or modparam declaration."""

    def __init__(self, kind, name, htype, direction, newapi=False, size=None,
                 size_expr=None, line=0):
        """Record one declaration as parsed."""
        self.kind = kind
        self.name = name
        self.type = htype
        self.dir = direction
        self.newapi = newapi
        self.size = size
        self.size_expr = size_expr
        self.line = line
        self.default = None
        self.cond = None
        self.doc = None

    @property
    def cname(self):
        """C identifier for this item."""
        return to_c(self.name)

    @property
    def field(self):
        """Member name in the generated instance structure."""
        return '__comp_' + to_c(self.name)

    @property
    def hal_name(self):
        """HAL name (printf pattern for arrays)."""
        return to_hal(self.name)

    @property
    def count_expr(self):
        """C expression giving the number of elements actually created."""
        return self.size_expr if self.size_expr else str(self.size)


class Component:
    """Everything halcompile knows about one .comp file."""

    def __init__(self, path):
        """An empty component read from path."""
        self.path = path
        self.name = None
        self.doc = None
        self.items = []
        self.options = {}
        self.docs = {}
        self.includes = []
        self.warnings = []
        self.code = ''
        self.code_line = 1
        self.code_has_function = False

    def add_item(self, item, err):
        """Add a declaration, checking reserved and duplicate names."""
        if item.name in RESERVED_NAMES or item.cname in RESERVED_NAMES:
            raise err('Variable name %s is reserved' % item.name)
        for other in self.items:
            if other.cname == item.cname or other.name == item.name:
                raise err('Duplicate item name %s' % item.name)
        self.items.append(item)

    def of_kind(self, kind):
        """All items of one kind, in declaration order."""
        return [i for i in self.items if i.kind == kind]

    @property
    def pins(self):
        """The pins, in declaration order."""
        return self.of_kind('pin')

    @property
    def params(self):
        """The params, in declaration order."""
        return self.of_kind('param')

    @property
    def functions(self):
        """The functions, in declaration order."""
        return self.of_kind('function')

    @property
    def variables(self):
        """The instance variables, in declaration order."""
        return self.of_kind('variable')

    @property
    def modparams(self):
        """The module parameters, in declaration order."""
        return self.of_kind('modparam')

    def option(self, name, default=None):
        """Value of an option, with yes/no normalised to True/False."""
        v = self.options.get(name, default)
        if isinstance(v, str) and v.lower() in ('yes', 'true', '1'):
            return True
        if isinstance(v, str) and v.lower() in ('no', 'false', '0'):
            return False
        return v

    @property
    def userspace(self):
        """True for a userspace (non-realtime) component."""
        return bool(self.option('userspace', False))

    @property
    def singleton(self):
        """True when the component has exactly one instance."""
        return bool(self.option('singleton') or self.option('homemod')
                    or self.option('tpmod'))

    @property
    def uses_personality(self):
        """True when any item depends on personality."""
        return any(i.cond or i.size_expr for i in self.items)

    @property
    def prefix_base(self):
        """HAL name prefix of the instances (hal_ stripped, _ as -)."""
        return hal_prefix_name(self.name)

    @property
    def license(self):
        """First line of the license declaration."""
        return self.docs['license'][0].split('\n')[0]

    def resolve_includes(self, directory):
        """Make '"..."' includes absolute relative to the .comp directory."""
        out = []
        for kind, hdr in self.includes:
            if kind == '"' and not os.path.isabs(hdr):
                hdr = os.path.join(directory, hdr)
            out.append((kind, hdr))
        self.includes = out


RESERVED_NAMES = ('comp_id', 'fperiod', 'rtapi_app_main', 'rtapi_app_exit',
                  'extra_setup', 'extra_cleanup', 'post_export')
