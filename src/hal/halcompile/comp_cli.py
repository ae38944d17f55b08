"""Command line of halcompile: option parsing and the per-file modes."""

import getopt
import os
import sys
import tempfile

from . import comp_build, comp_gen_main
from .comp_doc import document
from .comp_gen import generate
from .comp_lexer import CompError
from .comp_parse import parse_comp

USAGE = """Usage:
    halcompile [--compile|--preprocess|--document|--adoc|--view-doc] compfile...
    [sudo] halcompile [--install|--install-doc] compfile...
    halcompile --compile --userspace cfile...
    [sudo] halcompile --install --userspace cfile|pyfile...
    halcompile --print-modinc
Options:
    -p, --preprocess     write NAME.c (default)
    -c, --compile        build NAME.so (realtime) or NAME (userspace)
    -i, --install        build and install
    -d, --document       write the man page NAME.9 (NAME.1 for userspace)
    -a, --adoc           same as --document
    -k, --keep-adoc=FILE also write the page text to FILE
    -j, --install-doc    install the man page into share/man of the tree
    -J, --view-doc       show the man page
    -o, --outfile=FILE   output file (preprocess/document, one input)
    -u, --userspace      treat .c inputs as user programs
    -P, --personalities=N  maximum number of personalities (default 64)
    -U, --unix           accepted; CR line endings are always converted
    -h, --help           this text
"""

LONG = ['install', 'compile', 'preprocess', 'outfile=', 'document', 'adoc',
        'keep-adoc=', 'install-doc', 'view-doc', 'userspace', 'personalities=',
        'extra-compile-args=', 'extra-link-args=', 'unix', 'require-license',
        'help', 'print-modinc']


class Opts:
    """Settings collected from the command line."""
    mode = 'preprocess'
    outfile = None
    keep = None
    userspace = False
    unix = False
    cflags = ()
    ldflags = ()


def parse_args(argv):
    """Parse argv into (Opts, inputs); exits on usage errors."""
    try:
        pairs, args = getopt.gnu_getopt(argv, 'lUicpdajJk:o:uh?P:', LONG)
    except getopt.GetoptError:
        sys.stderr.write(USAGE)
        raise SystemExit(1)
    o = Opts()
    modes = {'-i': 'install', '--install': 'install', '-c': 'compile',
             '--compile': 'compile', '-p': 'preprocess', '--preprocess': 'preprocess',
             '-d': 'document', '--document': 'document', '-a': 'document',
             '--adoc': 'document', '-j': 'install-doc', '--install-doc': 'install-doc',
             '-J': 'view-doc', '--view-doc': 'view-doc'}
    for k, v in pairs:
        if k in modes:
            o.mode = modes[k]
        elif k in ('-o', '--outfile'):
            o.outfile = v
        elif k in ('-k', '--keep-adoc'):
            o.keep = v
        elif k in ('-u', '--userspace'):
            o.userspace = True
        elif k in ('-U', '--unix'):
            o.unix = True
        elif k in ('-P', '--personalities'):
            if not v.isdigit() or int(v) < 1:
                sys.stderr.write("halcompile: invalid number of personalities '%s'\n" % v)
                raise SystemExit(1)
            comp_gen_main.MAX_PERSONALITIES = int(v)
            print('MAX_PERSONALITIES=%d' % int(v))
        elif k == '--extra-compile-args':
            o.cflags = tuple(v.split())
        elif k == '--extra-link-args':
            o.ldflags = tuple(v.split())
        elif k in ('-h', '-?', '--help'):
            sys.stdout.write(USAGE)
            raise SystemExit(0)
        elif k == '--print-modinc':
            print(os.path.join(comp_build.tree_top(), 'src', 'hal', 'halcompile', 'Makefile.modinc'))
            raise SystemExit(0)
    return o, args


def read_comp(path, o, base_name):
    """Read and parse a .comp file; print errors and exit 1 on failure."""
    with open(path, 'rb') as f:
        raw = f.read().decode('utf-8', 'replace')
    text = raw.replace('\r\n', '\n').replace('\r', '\n')
    try:
        comp = parse_comp(path, text, base_name)
    except CompError as e:
        report(path, e)
        raise SystemExit(1)
    for line, msg in comp.warnings:
        sys.stderr.write('%s:%d: %s\n' % (path, line, msg))
    if comp.option('userinit') and not comp.userspace:
        sys.stderr.write("Warning: comp '%s' sets 'userinit' without 'userspace', "
                         "ignoring\n" % path)
    return comp


def report(path, e):
    """Print a CompError as FILE:LINE[:COL]: message (+ context)."""
    if e.col is None:
        sys.stderr.write('%s:%d: %s\n' % (path, e.line, e.msg))
        return
    sys.stderr.write('%s:%d:%d: %s\n' % (path, e.line, e.col, e.msg))
    sys.stderr.write('>  %s\n' % e.src_line)
    sys.stderr.write('>  %s^\n' % (' ' * (e.col - 1)))


def check_semantics(comp):
    """Errors found after the output was opened (exit 1, partial file kept)."""
    if not comp.pins:
        return 'Component must have at least one pin'
    if comp.userspace and comp.functions:
        return 'Userspace components may not have functions'
    if len(comp.functions) > 1 and not comp.code_has_function:
        return 'Must use FUNCTION() when more than one function is defined'
    return None


def write_c(comp, out_path):
    """Write the generated C file; exit 1 on semantic errors."""
    with open(out_path, 'w') as f:
        err = check_semantics(comp)
        if err:
            sys.stderr.write(err + '\n')
            raise SystemExit(1)
        f.write(generate(comp))


def base_of(path):
    """File name without directory and extension."""
    return os.path.splitext(os.path.basename(path))[0]


def do_comp(path, o):
    """Handle one .comp input in the selected mode."""
    if o.mode == 'preprocess':
        out = o.outfile or os.path.splitext(path)[0] + '.c'
        write_c(read_comp(path, o, base_of(out)), out)
        return
    if o.mode in ('document', 'install-doc', 'view-doc'):
        write_doc(path, o)
        return
    comp = read_comp(path, o, base_of(path))
    with tempfile.TemporaryDirectory(prefix='halcompile.') as tmp:
        csrc = os.path.join(tmp, comp.name + '.c')
        write_c(comp, csrc)
        build(comp.name, csrc, path, o, comp.userspace, comp)


def write_doc(path, o):
    """--document, --install-doc and --view-doc of one .comp file."""
    comp = read_comp(path, o, base_of(o.outfile or path))
    sect = '1' if comp.userspace else '9'
    text = document(comp)
    if o.keep:
        with open(o.keep, 'w') as f:
            f.write(text)
    if o.mode == 'view-doc':
        with tempfile.TemporaryDirectory(prefix='halcompile.') as tmp:
            page = os.path.join(tmp, comp.name + '.' + sect)
            with open(page, 'w') as f:
                f.write(text)
            comp_build.run(['man', '-l', page])
        return
    out = o.outfile or os.path.splitext(path)[0] + '.' + sect
    if o.mode == 'install-doc':
        out = os.path.join(comp_build.tree_top(), 'share', 'man', 'man' + sect,
                           comp.name + '.' + sect)
        os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, 'w') as f:
        f.write(text)


def build(name, csrc, orig, o, userspace, comp=None):
    """Compile (and maybe install) a C source for a realtime or user component."""
    cflags = list(o.cflags)
    ldflags = list(o.ldflags)
    if comp is not None:
        cflags += (comp.options.get('extra_compile_args') or '').split()
        ldflags += (comp.options.get('extra_link_args') or '').split()
    cflags.append('-I' + os.path.dirname(os.path.abspath(orig)))
    with tempfile.TemporaryDirectory(prefix='halcompile.') as tmp:
        if userspace:
            exe = os.path.join(tmp, name)
            comp_build.build_user(csrc, exe, cflags, ldflags)
            dest = comp_build.bin_install_dir() if o.mode == 'install' \
                else os.path.dirname(os.path.abspath(orig))
            comp_build.install_file(exe, dest, 0o755)
            return
        so = os.path.join(tmp, name + '.so')
        comp_build.build_rt(csrc, name, so, cflags)
        dest = comp_build.rt_install_dir() if o.mode == 'install' else os.getcwd()
        comp_build.install_file(so, dest, 0o644)


def do_file(path, o):
    """Dispatch one input file by extension and mode."""
    ext = os.path.splitext(path)[1]
    if ext == '.comp':
        do_comp(path, o)
    elif ext == '.c' and o.mode in ('compile', 'install'):
        build(base_of(path), os.path.abspath(path), path, o, o.userspace)
    elif ext == '.py' and o.mode == 'install':
        comp_build.install_python(path, comp_build.bin_install_dir())
    else:
        sys.stderr.write("Unrecognized file type for mode %s: '%s'\n" % (o.mode, path))
        raise SystemExit(1)


def main(argv):
    """Entry point; returns the exit status."""
    o, args = parse_args(argv)
    if o.outfile and o.mode not in ('preprocess', 'document'):
        sys.stderr.write('Can only specify -o when preprocessing or documenting\n')
        return 1
    if o.outfile and len(args) > 1:
        sys.stderr.write('Cannot specify -o with multiple input files\n')
        return 1
    if not args:
        sys.stderr.write(USAGE)
        return 1
    for path in args:
        if not os.path.exists(path):
            sys.stderr.write("%s: No such file\n" % path)
            return 1
        try:
            do_file(path, o)
        except OSError as e:
            sys.stderr.write('halcompile: %s: %s\n' % (e.filename or path, e.strerror))
            return 1
    return 0
