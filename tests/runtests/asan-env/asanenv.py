"""asanenv.py: run runtests_asan.add_sanitizer_environment on fake trees and use its wrappers."""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.environ["EMC2_HOME"], "scripts"))
import runtests_asan  # noqa: E402


CHILD = """
import os, subprocess
start = dict(v.split("=", 1) for v in open("/proc/self/environ").read().split("\\0") if "=" in v)
print("python3 started with LD_PRELOAD:", start.get("LD_PRELOAD"))
child = subprocess.run(["sh", "-c", "echo ${LD_PRELOAD:-none}"], stdout=subprocess.PIPE)
print("its children get LD_PRELOAD:", child.stdout.decode().strip())
"""


def fake_tree(root, asan_flags):
    """A tree with a Makefile.inc and a compiler that 'finds' runtimes in root/rt."""
    os.makedirs(os.path.join(root, "rt"))
    for lib in ("libasan.so", "libubsan.so"):
        open(os.path.join(root, "rt", lib), "w").close()
    cc = os.path.join(root, "fakecc")
    with open(cc, "w") as f:
        f.write('#!/bin/sh\necho "%s/rt/${1#-print-file-name=}"\n' % root)
    os.chmod(cc, 0o755)
    with open(os.path.join(root, "Makefile.inc"), "w") as f:
        f.write("CC = %s\nASAN_FLAGS = %s\n" % (cc, asan_flags))


def main():
    """Plain tree: environment untouched. ASan tree: wrappers run Python with the preload."""
    with tempfile.TemporaryDirectory() as work:
        plain, asan = os.path.join(work, "plain"), os.path.join(work, "asan")
        fake_tree(plain, "")
        fake_tree(asan, "-fsanitize=address,undefined -fno-omit-frame-pointer")
        env = {"PATH": os.environ["PATH"]}
        runtests_asan.add_sanitizer_environment(plain, env)
        print("plain tree unchanged:", env == {"PATH": os.environ["PATH"]})
        runtests_asan.add_sanitizer_environment(asan, env)
        runtests_asan.add_sanitizer_environment(asan, env)
        wrap = os.path.join(asan, "objects", "asan-python")
        print("wrappers first on PATH once:", env["PATH"].split(os.pathsep).count(wrap) == 1
              and env["PATH"].startswith(wrap + os.pathsep))
        print("suppressions:", env["LSAN_OPTIONS"].replace(asan, "TREE"))
        out = subprocess.run(["python3", "-c", CHILD], env=dict(os.environ, **env),
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             timeout=60).stdout.decode()
        print(out.strip().replace(asan, "TREE"))


main()
