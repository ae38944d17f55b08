#!/usr/bin/env python3
"""halcmd_twopass: run the [HAL]HALFILEs of an INI file in two passes (merged loadrt, then the rest)."""
import os
import re
import subprocess
import sys
import tempfile

COUNT_FORMS = ("count", "num_chan", "names")


def fail(msg):
    """Print an error and exit with status 1."""
    sys.stderr.write(msg + "\n")
    sys.exit(1)


def read_ini(path):
    """Return the list of (section, key, value) entries of an INI file, in file order."""
    entries, section = [], ""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                line = line.strip()
                if not line or line[0] in "#;":
                    continue
                if line.startswith("[") and "]" in line:
                    section = line[1:line.index("]")]
                elif "=" in line:
                    key, value = line.split("=", 1)
                    entries.append((section, key.strip(), value.strip()))
    except OSError as e:
        fail("halcmd_twopass: cannot read INI file '%s': %s" % (path, e.strerror))
    return entries


def strip_comment(text):
    """Cut text at the first '#' outside quotes (as halcmd does)."""
    quote = None
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c == "#":
            return text[:i]
    return text


def logical_lines(path):
    """Yield (first_line_index, n_physical_lines, text) with backslash continuation joined."""
    with open(path, encoding="utf-8", errors="replace") as f:
        raw = f.read().split("\n")
    if raw and raw[-1] == "":
        raw.pop()
    i = 0
    while i < len(raw):
        start, text = i, ""
        while True:
            line = raw[i].rstrip("\r") if raw[i].endswith("\\\r") else raw[i]
            i += 1
            if line.endswith("\\") and i < len(raw):
                text += line[:-1]
                continue
            text += line[:-1] if line.endswith("\\") else line
            break
        yield start, i - start, text


def first_word(text):
    """The command word of a HAL line ('' for blank or comment lines)."""
    words = strip_comment(text).split()
    return words[0] if words else ""


def substitute(text, ini_entries):
    """Replace $NAME, $(NAME), [SECTION]KEY and [SECTION](KEY) like halcmd does."""
    def env(m):
        """The value of the environment variable matched by m (it must exist)."""
        name = m.group(1) or m.group(2)
        if name not in os.environ:
            fail("Environment variable '%s' not found." % name)
        return os.environ[name]

    def ini(m):
        """The INI value matched by m; any section when the section is empty."""
        sec, key = m.group(1), m.group(2) or m.group(3)
        for s, k, v in ini_entries:
            if k == key and (sec == "" or s == sec):
                return v
        fail("Ini variable '[%s]%s' not found." % (sec, key))

    text = re.sub(r"\$\(([^)]*)\)|\$([0-9A-Za-z._-]+)", env, text)
    return re.sub(r"\[([^\]]*)\](?:\(([^)]*)\)|([0-9A-Za-z._-]+))", ini, text)


class Module:
    """All loadrt requests of one module, merged into a single loadrt."""

    def __init__(self, name):
        """An empty merge for module name."""
        self.name, self.form, self.count = name, None, 0
        self.names, self.personality, self.debug = [], [], None
        self.other, self.bare = {}, 0

    def add(self, args):
        """Merge the k=v arguments of one loadrt line."""
        for arg in args:
            key, _, value = arg.partition("=")
            if key in COUNT_FORMS:
                self.add_form(key, value)
            elif key == "personality":
                self.personality.append(value)
            elif key == "debug":
                self.debug = (self.debug or 0) | int(value, 0)
            else:
                self.other[key] = value
        if not any(a.partition("=")[0] in COUNT_FORMS for a in args):
            self.bare += 1

    def add_form(self, key, value):
        """Record count=/num_chan= (summed) or names= (joined); forms must not mix."""
        form = "names" if key == "names" else key
        if self.form not in (None, form):
            fail("loadrt_substitute: cannot mix count=, num_chan= and names= forms "
                 "for module '%s'" % self.name)
        self.form = form
        if form == "names":
            self.names.extend(n for n in value.split(",") if n)
        else:
            self.count += int(value, 0)

    def line(self):
        """The merged loadrt command."""
        words = ["loadrt", self.name]
        if self.form == "names":
            words.append("names=" + ",".join(self.names))
        elif self.form:
            words.append("%s=%d" % (self.form, self.count + self.bare))
        if self.personality:
            words.append("personality=" + ",".join(self.personality))
        if self.debug is not None:
            words.append("debug=%d" % self.debug)
        words += ["%s=%s" % kv for kv in self.other.items()]
        return " ".join(words)


def run_halcmd(opts, ini, path, shown_as):
    """Run halcmd on path, reporting messages under the name shown_as; returns its status."""
    proc = subprocess.run(["halcmd"] + opts + ["-i", ini, "-f", path],
                          stderr=subprocess.PIPE, text=True, errors="replace")
    sys.stdout.flush()
    sys.stderr.write(proc.stderr.replace(path + ":", shown_as + ":"))
    sys.stderr.flush()
    return proc.returncode


def pass0(files, ini_entries, opts, ini, tmpdir):
    """Collect loadrt lines, run loadusr lines and #NOTWOPASS files; load merged modules."""
    modules, status = {}, 0
    for path in files:
        if any(t.lstrip().startswith("#NOTWOPASS") for _, _, t in logical_lines(path)):
            status = run_halcmd(opts, ini, path, path) or status
            continue
        for start, _, text in logical_lines(path):
            cmd = first_word(text)
            if cmd == "loadrt":
                words = substitute(strip_comment(text), ini_entries).split()
                if len(words) > 1:
                    modules.setdefault(words[1], Module(words[1])).add(words[2:])
            elif cmd == "loadusr":
                status = run_one(opts, ini, tmpdir, [""] * start + [text], path) or status
    merged = os.path.join(tmpdir, "pass0.hal")
    with open(merged, "w") as f:
        f.write("".join(m.line() + "\n" for m in modules.values()))
    return run_halcmd(opts, ini, merged, "twopass:pass0") or status


def run_one(opts, ini, tmpdir, lines, shown_as):
    """Run one HAL line (preceded by blank lines so line numbers match) through halcmd."""
    path = os.path.join(tmpdir, "line.hal")
    with open(path, "w") as f:
        f.write("".join(line + "\n" for line in lines))
    return run_halcmd(opts, ini, path, shown_as)


def pass1(files, opts, ini, tmpdir):
    """Run every file again without its loadrt/loadusr lines (line numbers kept)."""
    status = 0
    for n, path in enumerate(files):
        lines = []
        notwopass = False
        for _, count, text in logical_lines(path):
            notwopass = notwopass or text.lstrip().startswith("#NOTWOPASS")
            if first_word(text) in ("loadrt", "loadusr"):
                lines += [""] * count
            else:
                lines += [text] + [""] * (count - 1)
        if notwopass:
            continue
        copy = os.path.join(tmpdir, "pass1-%d.hal" % n)
        with open(copy, "w") as f:
            f.write("".join(line + "\n" for line in lines))
        status = run_halcmd(opts, ini, copy, path) or status
        if status and "-k" not in opts:
            break
    return status


def halfiles(ini, entries):
    """The [HAL]HALFILE names as given (relative ones are relative to the INI file's directory)."""
    base = os.path.dirname(os.path.abspath(ini))
    files = []
    for sec, key, value in entries:
        if sec == "HAL" and key == "HALFILE" and value:
            name = value.split()[0]
            path = name if os.path.isabs(name) else os.path.join(base, name)
            if not name.endswith(".hal"):
                fail("halcmd_twopass: only .hal HALFILEs are supported: '%s'" % name)
            if not os.path.isfile(path):
                fail("halcmd_twopass: HALFILE '%s' not found" % name)
            files.append(name)
    return files


USAGE = """Usage: halcmd_twopass [halcmd options] file.ini
Runs the [HAL]HALFILE files of file.ini in two passes, as [HAL]TWOPASS asks: first every
loadrt/loadusr (repeated loads of one module merged into one), then all other commands.
halcmd options (-k, -v, ...) are passed to halcmd. TWOPASS words: verbose, nodelete.
"""


def main(argv):
    """halcmd_twopass [halcmd options] file.ini"""
    if argv and argv[0] in ("--help", "-h"):
        sys.stdout.write(USAGE)
        return 0
    if not argv or argv[-1].startswith("-"):
        fail("Usage: halcmd_twopass [halcmd options] file.ini")
    ini, opts = argv[-1], argv[:-1]
    entries = read_ini(ini)
    twopass = [v for s, k, v in entries if s == "HAL" and k == "TWOPASS"]
    if not twopass or not twopass[0]:
        fail("halrun: An INI file may only be used if it specifies [HAL]TWOPASS")
    words = twopass[0].split()
    files = halfiles(ini, entries)
    os.chdir(os.path.dirname(os.path.abspath(ini)))
    ini = os.path.abspath(os.path.basename(ini))
    tmpdir = tempfile.mkdtemp(prefix="twopass.")
    status = pass0(files, entries, opts, ini, tmpdir)
    if status == 0 or "-k" in opts:
        status = pass1(files, opts, ini, tmpdir) or status
    if "nodelete" in words:
        print("halcmd_twopass: temporary files kept in %s" % tmpdir)
    else:
        for name in os.listdir(tmpdir):
            os.unlink(os.path.join(tmpdir, name))
        os.rmdir(tmpdir)
    return 1 if status else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
