"""Compiling and installing generated or hand-written modules and programs."""

import os
import shutil
import subprocess
import tempfile

WARN = ['-Wall', '-Wextra']


def tree_top():
    """Root of the run-in-place tree holding this halcompile."""
    here = os.path.dirname(os.path.realpath(__file__))
    return os.path.realpath(os.path.join(here, '..', '..', '..'))


def headers_dir():
    """$HEADERS, else include/ of the tree."""
    return os.environ.get('HEADERS') or os.path.join(tree_top(), 'include')


def lib_dir():
    """$LIBDIR, else lib/ of the tree."""
    return os.environ.get('LIBDIR') or os.path.join(tree_top(), 'lib')


def rt_install_dir():
    """$USER_MODULE_DIR, else $RTLIB_DIR, else rtlib/ of the tree."""
    return (os.environ.get('USER_MODULE_DIR') or os.environ.get('RTLIB_DIR')
            or os.path.join(tree_top(), 'rtlib'))


def bin_install_dir():
    """bin/ of the tree."""
    return os.path.join(tree_top(), 'bin')


def run(cmd):
    """Run a command, echoing nothing; raise SystemExit with its status on failure."""
    r = subprocess.run(cmd)
    if r.returncode != 0:
        raise SystemExit(r.returncode if r.returncode > 0 else 1)


def export_names(obj):
    """Names recorded by EXPORT_SYMBOL() in an object's .rtapi_export section."""
    r = subprocess.run(['objcopy', '-O', 'binary', '-j', '.rtapi_export', obj,
                        '/dev/stdout'], capture_output=True)
    if r.returncode != 0:
        return []
    names = r.stdout.decode('latin-1').split('\0')
    return sorted(set(n for n in names if n.isidentifier()))


def write_version_script(path, obj):
    """Linker version script keeping only the module's public symbols."""
    with open(path, 'w') as f:
        f.write('{ global: rtapi_app_main; rtapi_app_exit; rtapi_info_*; rtapi_export_*;\n')
        for n in export_names(obj):
            f.write('    %s;\n' % n)
        f.write('  local: *; };\n')


def build_rt(csrc, name, out_so, extra_cflags=()):
    """Compile a realtime module from csrc into out_so."""
    tmp = tempfile.mkdtemp(prefix='halcompile.')
    try:
        obj = os.path.join(tmp, name + '.o')
        ver = os.path.join(tmp, name + '.ver')
        run(['gcc', '-std=gnu11', '-O2', '-g', '-fPIC', '-DRTAPI'] + WARN +
            ['-I' + headers_dir(), '-I' + os.path.dirname(os.path.abspath(csrc))] +
            list(extra_cflags) + ['-c', csrc, '-o', obj])
        write_version_script(ver, obj)
        tmp_so = os.path.join(tmp, name + '.so')
        run(['gcc', '-shared', '-Wl,--version-script=' + ver, '-o', tmp_so, obj, '-lm'])
        shutil.copyfile(tmp_so, out_so)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def sanitizer_flags():
    """ASAN_FLAGS of the tree's Makefile.inc (configure --enable-asan): a program linking the
    tree's sanitizer-built libraries needs the same flags so their runtime comes first."""
    try:
        with open(os.path.join(tree_top(), 'Makefile.inc')) as f:
            for line in f:
                key, sep, value = line.partition('=')
                if sep and key.strip() == 'ASAN_FLAGS':
                    return value.split()
    except OSError:
        pass
    return []


def build_user(csrc, out_exe, extra_cflags=(), extra_ldflags=()):
    """Compile a userspace HAL program."""
    lib = lib_dir()
    run(['gcc', '-std=gnu11', '-O2', '-g', '-DULAPI'] + WARN + sanitizer_flags() +
        ['-I' + headers_dir(), '-I' + os.path.dirname(os.path.abspath(csrc))] +
        list(extra_cflags) + [csrc, '-o', out_exe, '-L' + lib, '-Wl,-rpath,' + lib,
                              '-llinuxcnchal', '-lrtapi', '-lm'] + list(extra_ldflags))


def install_file(src, dest_dir, mode):
    """Copy src into dest_dir with mode (via a temporary file and rename)."""
    os.makedirs(dest_dir, exist_ok=True)
    dest = os.path.join(dest_dir, os.path.basename(src))
    tmp = dest + '.tmp%d' % os.getpid()
    shutil.copyfile(src, tmp)
    os.chmod(tmp, mode)
    os.replace(tmp, dest)
    return dest


def install_python(src, dest_dir):
    """Install a .py userspace component with a python3 #! line, mode 0555."""
    name = os.path.splitext(os.path.basename(src))[0]
    with open(src) as f:
        lines = f.read().split('\n')
    if lines and lines[0].startswith('#!'):
        lines = lines[1:]
    os.makedirs(dest_dir, exist_ok=True)
    dest = os.path.join(dest_dir, name)
    tmp = dest + '.tmp%d' % os.getpid()
    with open(tmp, 'w') as f:
        f.write('#!/usr/bin/env python3\n' + '\n'.join(lines))
    os.chmod(tmp, 0o555)
    os.replace(tmp, dest)
