"""raster_test.py: writes raster programs (offset;bpp;ppu;count;pixels) into a HAL port, drives run and
reset, and traces raster.0 one period per row."""
import subprocess
import sys
import time

import hal

COLUMNS = "position state enabled fault fault-code current-pixel-index bitmap-position output"


def halcmd(*args):
    """Run one halcmd command, failing the test when it fails."""
    subprocess.run(["halcmd", *args], check=True)


def wait_streamer_empty():
    """Poll until the streamer has taken its last row, so a stop cannot leave rows behind."""
    for _ in range(6000):
        if hal.get_value("streamer.0.curr-depth") == 0:
            return
        time.sleep(0.01)
    print("streamer never emptied")
    sys.exit(1)


def scenario(port, title, program, rows, end_reset=True):
    """Write PROGRAM, stream ROWS (position, reset, run), print one sampled line per row.

    Two rows follow: one sampled (so halsampler returns only after raster has seen its reset
    value) and one unsampled with the same reset, which stops the sampler."""
    print("##", title)
    if program and not port.write(program):
        print("port write refused")
        sys.exit(1)
    lines = ["%s %d %d 1" % row for row in rows]
    lines.append("0 %d 0 1" % (1 if end_reset else 0))
    lines.append("0 %d 0 0" % (1 if end_reset else 0))
    subprocess.run(["halstreamer"], input="\n".join(lines) + "\n", text=True, check=True)
    halcmd("start")
    out = subprocess.run(["halsampler", "-n", str(len(rows) + 1)], capture_output=True,
                         text=True, check=True).stdout
    wait_streamer_empty()
    halcmd("stop")
    for row, line in zip(rows, out.splitlines()):
        flags = (" reset" if row[1] else "") + ("" if row[2] else " no-run")
        print(line.rstrip() + flags)


def passes(port):
    """Forward and reverse lines, interpolation, off pixels, the end of the line, run dropped."""
    scenario(port, "forward, 4 bits per pixel: 0 F 8 A 3 (0%, off, 57.1%, 71.4%, 21.4%), 2 pixels/unit",
             "0;4;2;5;0F8A3",
             [(1.0, 0, 1), (1.0, 0, 1), (1.25, 0, 1), (1.5, 0, 1), (1.75, 0, 1), (2.0, 0, 1),
              (2.25, 0, 1), (3.0, 0, 1), (3.5, 0, 1), (3.5, 0, 0)])
    scenario(port, "negative offset: swept downward from 1 below the start, 8 bits 00 FF 80",
             "-1;8;10;3;00FF80",
             [(5.0, 0, 1), (4.05, 0, 1), (4.0, 0, 1), (3.95, 0, 1), (3.8, 0, 1), (3.8, 0, 0)])
    digits = ("0123456789ABCDE" * 80)[:1100]
    scenario(port, "1100 pixels from 0.5, 100 pixels/unit", "0.5;4;100;1100;" + digits,
             [(0.0, 0, 1), (0.5, 0, 1), (0.6, 0, 1), (11.49, 0, 1), (11.49, 0, 0)])
    scenario(port, "32 bits per pixel", "0;32;1;2;FFFFFFFE7FFFFFFF",
             [(0.0, 0, 1), (0.0, 0, 1), (0.5, 0, 1), (1.0, 0, 1), (1.0, 0, 0)])
    scenario(port, "reset while running: idle, the port emptied", "0;4;1;2;E0",
             [(0.0, 0, 1), (0.0, 0, 1), (0.0, 1, 1), (0.0, 0, 0)])


def faults(port):
    """Malformed programs: fault code at once, fault one period later, until reset."""
    bad = [("x;4;1;2;00", "offset not a number"), ("1" * 40 + ";4;1;2;00", "offset field too long"),
           ("0;3;1;2;00", "3 bits per pixel"), ("0;36;1;2;00", "36 bits per pixel"),
           ("0;4;0;2;00", "0 pixels per unit"), ("0;4;-1;2;00", "negative pixels per unit"),
           ("0;4;1;1;0", "1 pixel"), ("0;4;1;3;00", "2 pixels for a count of 3"),
           ("0;4;1;2;000", "3 pixels for a count of 2")]
    for program, why in bad:
        scenario(port, "bad program (%s): %r" % (why, program), program,
                 [(0.0, 0, 1), (0.0, 0, 1), (0.0, 1, 0), (0.0, 0, 0)])
    scenario(port, "bad hex digit: found when the pixel is read", "0;4;1;2;0G",
             [(0.0, 0, 1), (0.0, 0, 1), (0.5, 0, 1), (0.5, 0, 1), (0.5, 1, 0), (0.5, 0, 0)])


def main():
    """Create the port writer, build the HAL graph and run every scenario."""
    comp = hal.component("feed")
    port = comp.newpin("program", hal.HAL_PORT, hal.HAL_OUT)
    comp.ready()
    halcmd("-f", "setup.hal")
    print("columns:", COLUMNS)
    passes(port)
    faults(port)


main()
