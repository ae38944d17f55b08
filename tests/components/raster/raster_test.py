"""raster_test.py: writes raster programs into a HAL port and traces raster.0 one period per row."""
import subprocess
import sys
import time

import hal

COLUMNS = "position state run fault fault-code current-pixel output"


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
    """Write PROGRAM, stream ROWS (position, reset, enable), print one sampled line per row.

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
        flags = (" reset" if row[1] else "") + ("" if row[2] else " disabled")
        print(line.rstrip() + flags)


def passes(port):
    """Forward and reverse passes, queued programs, long and split programs."""
    scenario(port, "forward pass, 4 bits per pixel: 0 F 8 A 3 from 1.0, 2 pixels/unit", "2;1.0;4;5;0F8A3",
             [(0.5, 0, 1), (1.25, 0, 1), (1.75, 0, 1), (2.25, 0, 1), (2.4, 0, 0), (2.75, 0, 1),
              (3.25, 0, 1), (3.6, 0, 1), (3.7, 0, 1)])
    scenario(port, "reverse pass, 1 bit per pixel (A5), then the queued 8-bit program runs",
             "10;-0.4;1;8;A5\n2;0;8;2;FF80",
             [(x / 100.0, 0, 1) for x in range(45, -46, -10)] +
             [(-0.45, 0, 1), (0.25, 0, 1), (0.75, 0, 1), (1.2, 0, 1)])
    digits = ("0123456789ABCDEF" * 69)[:1100]
    scenario(port, "1100 pixels: more than 1024 bytes, loaded over two periods", "100;0;4;1100;" + digits,
             [(10.985, 0, 1), (10.985, 0, 1), (0.005, 0, 1), (5.005, 0, 1)])
    scenario(port, "16 bits per pixel; reset while running drops the program", "1;0;16;2;FFFF8000",
             [(0.5, 0, 1), (1.5, 0, 1), (1.5, 1, 1), (1.5, 0, 1)])
    scenario(port, "program in three pieces: '4;0.'", "4;0.", [(0.1, 0, 1), (0.1, 0, 1)], False)
    scenario(port, "second piece '0;2;4;E'", "0;2;4;E", [(0.1, 0, 1)], False)
    scenario(port, "last piece '4': 2-bit pixels 3 2 1 0", "4",
             [(0.1, 0, 1), (0.3, 0, 1), (0.6, 0, 1), (0.9, 0, 1), (1.1, 0, 1)])
    scenario(port, "whitespace before a program is skipped", "\n\r\t 1;0;4;1;F", [(0.5, 0, 1)])


def faults(port):
    """Malformed programs: fault state and code until reset, which empties the port."""
    bad = [("0;0;4;2;00", "pixels per unit 0"), ("-1;0;4;2;00", "negative pixels per unit"),
           ("1" * 40 + ";0;4;2;00", "field too long"), ("1e3;0;4;2;00", "exponent"),
           ("1;1.2.3;4;2;00", "two decimal points"), ("1;;4;2;00", "empty offset"),
           ("1;0;0;2;00", "0 bits per pixel"), ("1;0;17;2;00", "17 bits per pixel"),
           ("1;0;4.0;2;00", "fractional bits per pixel"), ("1;0;4;0;", "0 pixels"),
           ("1;0;4;8193;", "8193 pixels"), ("1;0;4;-2;", "negative count"),
           ("1;0;4;2;0 0", "space in pixel data"),
           ("1;0;4;3;0G01;0;4;2;FF", "bad hex digit; the program after it is discarded by reset")]
    for program, why in bad:
        scenario(port, "bad program (%s): %r" % (why, program), program,
                 [(0.5, 0, 1), (0.5, 0, 1), (0.5, 1, 1), (0.5, 0, 1)])


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
