#!/usr/bin/env python3
"""halplot: samples HAL pins/signals on a thread (or reads a sampler channel) into a CSV and a PNG."""
import os
import subprocess
import sys

sys.path.insert(1, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "lib", "python"))
import halplot_png  # noqa: E402

USAGE = """Usage: halplot -t THREAD [-n COUNT] [-o BASE] NAME...
       halplot -c CHAN [-n COUNT] [-o BASE] [LABEL...]
Samples each pin or signal NAME once per period of THREAD (through its own sampler
module) or reads COUNT records of an existing sampler channel CHAN, then writes
BASE.csv and BASE.png (default BASE: halplot). Threads must be running.
"""
TYPE_LETTERS = {"bit": "b", "float": "f", "s32": "s", "u32": "u", "s64": "l", "u64": "k"}
MAX_ITEMS = 21


class PlotError(Exception):
    """A user error: printed as `halplot: ERROR: ...`, exit status 1."""


def halcmd(*args):
    """Run halcmd; return stdout, raising PlotError with its stderr on failure."""
    done = subprocess.run(["halcmd"] + list(args), capture_output=True, text=True)
    if done.returncode != 0:
        raise PlotError("halcmd %s failed: %s" % (" ".join(args), done.stderr.strip()))
    return done.stdout


def parse_args(argv):
    """Return dict thread, chan, count, base, names; raises PlotError."""
    opts = {"thread": None, "chan": None, "count": 100, "base": "halplot", "names": []}
    i = 0
    while i < len(argv):
        arg = argv[i]
        if arg in ("-h", "--help"):
            sys.stdout.write(USAGE)
            sys.exit(0)
        if arg in ("-t", "-c", "-n", "-o"):
            if i + 1 >= len(argv):
                raise PlotError("option '%s' needs a value" % arg)
            opts[{"-t": "thread", "-c": "chan", "-n": "count", "-o": "base"}[arg]] = argv[i + 1]
            i += 2
            continue
        if arg.startswith("-"):
            raise PlotError("unknown option '%s'" % arg[1:])
        opts["names"].append(arg)
        i += 1
    return check_args(opts)


def check_args(opts):
    """Validate the parsed options."""
    if not str(opts["count"]).isdigit() or int(opts["count"]) < 1:
        raise PlotError("invalid sample count '%s'" % opts["count"])
    opts["count"] = int(opts["count"])
    if (opts["thread"] is None) == (opts["chan"] is None):
        raise PlotError("give exactly one of -t THREAD and -c CHAN")
    if opts["chan"] is not None and opts["chan"] not in [str(n) for n in range(8)]:
        raise PlotError("invalid channel number '%s'" % opts["chan"])
    if opts["thread"] is not None and not opts["names"]:
        raise PlotError("no pins or signals to sample")
    if len(opts["names"]) > MAX_ITEMS:
        raise PlotError("at most %d pins or signals" % MAX_ITEMS)
    return opts


def find_item(name):
    """Return (type word, signal name or None, is_pin) of a pin or signal NAME."""
    done = subprocess.run(["halcmd", "-s", "show", "pin", name], capture_output=True, text=True)
    for line in done.stdout.splitlines():
        words = line.split()
        if len(words) >= 5 and words[4] == name:
            signal = words[6] if len(words) >= 7 else None
            return words[1], signal, True
    done = subprocess.run(["halcmd", "stype", name], capture_output=True, text=True)
    if done.returncode == 0 and done.stdout.strip() in TYPE_LETTERS:
        return done.stdout.strip(), name, False
    raise PlotError("'%s' is neither a pin nor a signal" % name)


def plan_links(names):
    """Return (cfg letters, [(signal, pin-or-None, created)]) for the named items."""
    cfg, links = "", []
    for index, name in enumerate(names):
        kind, signal, is_pin = find_item(name)
        if kind not in TYPE_LETTERS:
            raise PlotError("'%s' has type %s, which cannot be sampled" % (name, kind))
        cfg += TYPE_LETTERS[kind]
        if signal is not None:
            links.append((signal, None, False))
        else:
            links.append(("halplot-%d" % index, name, True))
    return cfg, links


def keep_signal_value(signal, sampler_pin):
    """Preset the sampler pin to the signal's value: linking copies the pin into a reader-less signal."""
    value = halcmd("gets", signal).strip()
    value = {"TRUE": "1", "FALSE": "0"}.get(value, value)
    halcmd("setp", sampler_pin, value)


def setup_sampler(thread, count, names, undo):
    """Load a private sampler channel 0 wired to the items; records undo steps in undo."""
    done = subprocess.run(["halcmd", "list", "comp", "sampler"], capture_output=True, text=True)
    if "sampler" in done.stdout.split():
        raise PlotError("sampler is already loaded; read its channel with -c CHAN")
    cfg, links = plan_links(names)
    halcmd("loadrt", "sampler", "depth=%d" % (count + 1), "cfg=" + cfg)
    undo.append(("unloadrt", "sampler"))
    for index, (signal, pin, created) in enumerate(links):
        sampler_pin = "sampler.0.pin.%d" % index
        if pin is None:
            keep_signal_value(signal, sampler_pin)
            halcmd("net", signal, sampler_pin)
        else:
            halcmd("net", signal, pin, sampler_pin)
        if created:
            undo.insert(0, ("delsig", signal))
    halcmd("addf", "sampler.0", thread)
    undo.insert(0, ("delf", "sampler.0", thread))


def read_records(chan, count):
    """Run halsampler and return the records as lists of text fields."""
    done = subprocess.run(["halsampler", "-c", str(chan), "-n", str(count)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise PlotError(done.stderr.strip() or "halsampler failed")
    return [line.split() for line in done.stdout.splitlines() if line != "overrun"]


def write_outputs(base, labels, records):
    """Write BASE.csv and BASE.png from the records."""
    width = max((len(r) for r in records), default=0)
    labels = list(labels) + ["field%d" % n for n in range(len(labels), width)]
    tmp = base + ".csv.tmp"
    with open(tmp, "w") as out:
        out.write(",".join(["sample"] + labels[:width]) + "\n")
        for number, record in enumerate(records):
            out.write(",".join([str(number)] + record) + "\n")
    os.replace(tmp, base + ".csv")
    traces = [[float(r[n]) for r in records if n < len(r)] for n in range(width)]
    halplot_png.write_png(base + ".png", traces)


def run(opts):
    """Sample as requested and write the outputs."""
    undo = []
    try:
        if opts["thread"] is not None:
            setup_sampler(opts["thread"], opts["count"], opts["names"], undo)
            records = read_records(0, opts["count"])
        else:
            records = read_records(opts["chan"], opts["count"])
    finally:
        for step in undo:
            subprocess.run(["halcmd"] + list(step), capture_output=True)
    write_outputs(opts["base"], opts["names"], records)
    print("halplot: wrote %d samples to %s.csv and %s.png" % (len(records), opts["base"], opts["base"]))


def main(argv):
    """Entry point; returns the exit status."""
    try:
        run(parse_args(argv))
    except PlotError as exc:
        sys.stderr.write("halplot: ERROR: %s\n" % exc)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
