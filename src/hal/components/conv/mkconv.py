#!/usr/bin/env python3
"""mkconv.py: write conv_IN_OUT.comp from conv.comp.in (the 29 conv_* components share one template).

Usage: mkconv.py TEMPLATE IN OUT OUTFILE. The template's @@name ... @@end sections are kept or dropped
by the conversion's kind and @NAME@ words are replaced; the file is written to a temporary name and
renamed."""
import os
import sys

# type: (C type, smallest, largest, smallest as a literal, largest as a literal, float bounds)
TYPES = {
    'bit': ('hal_bit_t', 0, 1, '0', '1', None),
    's32': ('int32_t', -2**31, 2**31 - 1, '(-2147483648LL)', '2147483647LL', ('-2147483648.0', '2147483648.0')),
    'u32': ('uint32_t', 0, 2**32 - 1, '0LL', '4294967295LL', ('0.0', '4294967296.0')),
    's64': ('int64_t', -2**63, 2**63 - 1, '(-9223372036854775807LL - 1)', '9223372036854775807LL',
            ('-9223372036854775808.0', '9223372036854775808.0')),
    'u64': ('uint64_t', 0, 2**64 - 1, '0LL', '18446744073709551615ULL', ('0.0', '18446744073709551616.0')),
    'float': ('double', None, None, None, None, None),
}


def sections(src, keep):
    """Lines of src with the @@name sections not in keep removed (sections nest)."""
    out, stack = [], []
    for line in src.splitlines():
        if line.startswith('@@end'):
            stack.pop()
        elif line.startswith('@@'):
            stack.append(line[2:].strip())
        elif all(name in keep for name in stack):
            out.append(line)
    return '\n'.join(out) + '\n'


def kinds(src_t, dst_t):
    """The template sections that apply to a conversion from src_t to dst_t."""
    s, d = TYPES[src_t], TYPES[dst_t]
    if dst_t == 'float':
        return {'lossless'}
    if src_t == 'float':
        return {'ranged', 'from_float', 'unsigned_out' if d[1] == 0 else 'signed_out'}
    if s[1] >= d[1] and s[2] <= d[2]:
        return {'lossless'}
    keep = {'ranged', 'from_int'}
    if s[2] > d[2]:
        keep.add('upper')
    if s[1] < d[1]:
        keep.add('lower')
    return keep


def main():
    template, src_t, dst_t, outfile = sys.argv[1:5]
    d = TYPES[dst_t]
    text = sections(open(template).read(), kinds(src_t, dst_t))
    words = {'IN': src_t, 'OUT': dst_t, 'IN_C': TYPES[src_t][0], 'OUT_C': d[0],
             'MIN': d[3] or '', 'MAX': d[4] or '', 'MIN_F': d[5][0] if d[5] else '', 'END_F': d[5][1] if d[5] else ''}
    for key, value in words.items():
        text = text.replace('@%s@' % key, value)
    text = text.replace('} else\n    if', '} else if').replace('} else\n    {', '} else {')
    tmp = outfile + '.tmp'
    with open(tmp, 'w') as f:
        f.write(text)
    os.replace(tmp, outfile)


main()
