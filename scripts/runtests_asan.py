"""runtests_asan: test environment for a tree configured with --enable-asan (ASan + UBSan)."""

import os
import shutil
import subprocess
import sys


def make_variable(topdir, name):
    """Value of NAME in the tree's Makefile.inc (written by configure), or ''."""
    try:
        with open(os.path.join(topdir, "Makefile.inc"), errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return ""
    for line in lines:
        key, sep, value = line.partition("=")
        if sep and key.strip() == name:
            return value.strip()
    return ""


def sanitizer_runtime(cc, name):
    """Real path of a sanitizer runtime library as the compiler finds it, or None."""
    try:
        found = subprocess.run([cc, "-print-file-name=" + name], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, check=True).stdout.decode().strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return os.path.realpath(found) if os.path.isabs(found) and os.path.exists(found) else None


WRAP_SUBDIR = os.path.join("objects", "asan-python")
USERCUSTOMIZE = '''"""usercustomize: written by runtests; the python wrapper beside it preloaded the
sanitizer runtimes for this interpreter only: give its children the caller's LD_PRELOAD."""
import os

_SAVED = os.environ.pop("OPENEMC_ASAN_CALLER_PRELOAD", None)
if _SAVED:
    os.environ["LD_PRELOAD"] = _SAVED
elif _SAVED is not None:
    os.environ.pop("LD_PRELOAD", None)
'''


def write_file(path, text, mode):
    """Write a file atomically (concurrent runners write the same content)."""
    tmp = "%s.%d" % (path, os.getpid())
    with open(tmp, "w") as f:
        f.write(text)
    os.chmod(tmp, mode)
    os.replace(tmp, path)


def wrapper_text(name, real, libs):
    """Shell wrapper running `real` with the runtimes preloaded and the wrapper directory on
    PYTHONPATH, whose usercustomize restores the caller's LD_PRELOAD for child processes."""
    return ('#!/bin/sh\n# %s with the ASan runtime loaded first (written by runtests)\n'
            'OPENEMC_ASAN_CALLER_PRELOAD="$LD_PRELOAD" '
            'PYTHONPATH="${0%%/*}${PYTHONPATH:+:$PYTHONPATH}" '
            'LD_PRELOAD="%s${LD_PRELOAD:+ $LD_PRELOAD}" exec "%s" "$@"\n' % (name, " ".join(libs), real))


def python_wrappers(topdir, env, libs):
    """Write objects/asan-python/python3 (and python, python3.N): wrappers that start the
    interpreter found on PATH with the sanitizer runtimes preloaded; return their directory."""
    wrap_dir = os.path.join(topdir, WRAP_SUBDIR)
    os.makedirs(wrap_dir, exist_ok=True)
    search = os.pathsep.join(d for d in env.get("PATH", "").split(os.pathsep)
                             if d and not os.path.realpath(d).endswith(os.sep + WRAP_SUBDIR))
    write_file(os.path.join(wrap_dir, "usercustomize.py"), USERCUSTOMIZE, 0o644)
    for name in ("python3", "python", "python3.%d" % sys.version_info[1]):
        real = shutil.which(name, path=search)
        if real:
            write_file(os.path.join(wrap_dir, name), wrapper_text(name, real, libs), 0o755)
    return wrap_dir


def add_sanitizer_environment(topdir, env):
    """On a tree configured with --enable-asan: put python wrappers first on PATH, since an
    uninstrumented Python must load the ASan/UBSan runtimes first to import our ASan-built
    extensions, and suppress the leaks that uninstrumented programs (Python and whatever it
    starts: bash, the compiler, the linker) report at exit."""
    flags = make_variable(topdir, "ASAN_FLAGS")
    if "-fsanitize=" not in flags:
        return
    cc = make_variable(topdir, "CC") or "gcc"
    names = ["libasan.so"] + (["libubsan.so"] if "undefined" in flags else [])
    libs = [lib for lib in (sanitizer_runtime(cc, n) for n in names) if lib]
    wrap_dir = python_wrappers(topdir, env, libs)
    if env.get("PATH", "").split(os.pathsep)[0] != wrap_dir:
        env["PATH"] = wrap_dir + os.pathsep + env.get("PATH", "")
    supp = os.path.join(topdir, "scripts", "runtests-lsan.supp")
    options = "suppressions=%s:print_suppressions=0" % supp
    current = env.get("LSAN_OPTIONS", "")
    if options not in current:
        env["LSAN_OPTIONS"] = options + (":" + current if current else "")
