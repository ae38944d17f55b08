"""C code generation: the convenience macros that bind item names for user code."""

UNUSED = '__attribute__((unused))'


def _access(item):
    """Macro argument list, set-macro arguments and index for a scalar or an array item."""
    if item.size is None:
        return '', 'v', ''
    return '(i)', 'i, v', '[i]'


def pin_macros(item):
    """Macro lines for one pin."""
    n, f = item.cname, item.field
    ro = item.dir == 'in'
    args, set_args, index = _access(item)
    ref = '(*(__comp_inst->%s[i]))' % f if index else '(*__comp_inst->%s)' % f
    lines = ['#define %s_ptr%s (__comp_inst->%s%s)' % (n, args, f, index)]
    if item.type == 'port':
        # a port pin names its hal_port_t *, what hal_port_read() and friends take (LinuxCNC's hal.h)
        lines.append('#define %s%s (__comp_inst->%s%s)' % (n, args, f, index))
    elif item.newapi:
        lines.append('#define %s%s (0+%s)' % (n, args, ref))
        if not ro:
            lines.append('#define %s_set(%s) (%s = (v))' % (n, set_args, ref))
    else:
        lines.append('#define %s%s %s' % (n, args, '(0+%s)' % ref if ro else ref))
    return lines


def param_macros(item):
    """Macro lines for one param."""
    n, f = item.cname, item.field
    args, set_args, index = _access(item)
    ref = '(__comp_inst->%s%s)' % (f, index)
    if item.newapi:
        return ['#define %s%s (0+%s)' % (n, args, ref),
                '#define %s_set(%s) (%s = (v))' % (n, set_args, ref)]
    return ['#define %s%s %s' % (n, args, ref)]


def hook_macros(comp):
    """FUNCTION/EXTRA_SETUP/EXTRA_CLEANUP/POST_EXPORT/FOR_ALL_INSTS."""
    inst = 'struct __comp_state *__comp_inst %s' % UNUSED
    lines = ['#undef FUNCTION',
             '#define FUNCTION(name) static void name(%s, long period %s)' % (inst, UNUSED),
             '#undef EXTRA_SETUP',
             '#define EXTRA_SETUP() static int extra_setup(%s, char *prefix %s, '
             'long extra_arg %s)' % (inst, UNUSED, UNUSED),
             '#undef EXTRA_CLEANUP',
             '#define EXTRA_CLEANUP() static void extra_cleanup(void)',
             '#undef POST_EXPORT',
             '#define POST_EXPORT() static int post_export(%s, char *prefix %s, '
             'long extra_arg %s)' % (inst, UNUSED, UNUSED),
             '#undef FOR_ALL_INSTS',
             '#define FOR_ALL_INSTS() struct __comp_state *__comp_inst; '
             'for (__comp_inst = __comp_first_inst; __comp_inst; '
             '__comp_inst = __comp_inst->_next)']
    if comp.option('period') is not False:
        lines.append('#undef fperiod')
        lines.append('#define fperiod (period * 1e-9)')
    return lines


def gen_macros(comp, out):
    """All macros, emitted just before the user's C code."""
    out.extend(hook_macros(comp))
    if comp.option('no_convenience_defines'):
        out.append('')
        return
    if comp.uses_personality:
        out.append('#undef personality')
        out.append('#define personality (__comp_inst->personality)')
    for item in comp.items:
        if item.kind in ('pin', 'param', 'variable'):
            out.append('#undef %s' % item.cname)
        if item.kind == 'pin':
            out.extend(pin_macros(item))
        elif item.kind == 'param':
            out.extend(param_macros(item))
        elif item.kind == 'variable':
            out.append('#define %s (__comp_inst->%s)' % (item.cname, item.field))
    if comp.option('data'):
        out.append('#undef data')
        out.append('#define data (*(%s *)__comp_inst->_data)' % comp.option('data'))
    out.append('')
