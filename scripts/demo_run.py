#!/usr/bin/env python3
"""demo_run.py: drive the running demo mill: home, run a part program with a progress line,
report cycle time, tool changes and following error, and draw the toolpath (PNG)."""
import math
import os
import struct
import subprocess
import sys
import time
import zlib

import linuxcnc

c = linuxcnc.command()
s = linuxcnc.stat()
e = linuxcnc.error_channel()


def wait(cond, timeout, what):
    end = time.time() + timeout
    while time.time() < end:
        s.poll()
        if cond():
            return
        time.sleep(0.005)
    sys.exit("demo: timeout waiting for %s" % what)


def wait_ready():
    end = time.time() + 20
    while time.time() < end:
        try:
            s.poll()
            if s.taskbeat > 0 and s.linear_units != 0:
                return
        except linuxcnc.error:
            pass
        time.sleep(0.02)
    sys.exit("demo: the machine did not start")


def programmed_path(ngc, tbl):
    """The interpreter's path (rs274 canon output): a list of polylines in program mm."""
    out = subprocess.run(["rs274", "-g", "-t", tbl, ngc], capture_output=True, text=True, check=True).stdout
    pts, cur = [], (0.0, 0.0)
    for line in out.splitlines():
        name, _, args = line.partition("(")
        name = name.split()[-1] if name.split() else ""
        vals = [float(v) for v in args.rstrip(")").replace(",", " ").split()] if name.endswith(("FEED", "TRAVERSE")) else []
        if name in ("STRAIGHT_FEED", "STRAIGHT_TRAVERSE") and len(vals) >= 2:
            cur = (vals[0], vals[1])
            pts.append(cur)
        elif name == "ARC_FEED" and len(vals) >= 5:
            (ex, ey, cx, cy, rot) = vals[:5]
            a0 = math.atan2(cur[1] - cy, cur[0] - cx)
            a1 = math.atan2(ey - cy, ex - cx)
            sweep = (a1 - a0) if rot > 0 else (a0 - a1)
            while sweep <= 1e-9:
                sweep += 2 * math.pi
            r = math.hypot(cur[0] - cx, cur[1] - cy)
            for k in range(1, 33):
                a = a0 + (sweep if rot > 0 else -sweep) * k / 32
                pts.append((cx + r * math.cos(a), cy + r * math.sin(a)))
            cur = (ex, ey)
    return pts


def distance_to_path(p, path):
    best = float("inf")
    for (ax, ay), (bx, by) in zip(path, path[1:]):
        dx, dy = bx - ax, by - ay
        l2 = dx * dx + dy * dy
        t = 0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / l2))
        best = min(best, math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy))
    return best


def write_png(path, w, h, pixels):
    """pixels: bytearray of w*h*3 RGB bytes."""
    raw = b"".join(b"\0" + bytes(pixels[y * w * 3:(y + 1) * w * 3]) for y in range(h))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xffffffff)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path + ".tmp", "wb") as f:
        f.write(png)
    os.replace(path + ".tmp", path)


def draw(path, programmed, sampled, size=480):
    xs = [p[0] for p in programmed + sampled]
    ys = [p[1] for p in programmed + sampled]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    scale = (size - 40) / max(x1 - x0, y1 - y0, 1e-6)
    pix = bytearray(b"\xff" * size * size * 3)

    def plot(x, y, rgb):
        px = int(20 + (x - x0) * scale)
        py = int(size - 20 - (y - y0) * scale)
        for dx in (0, 1):
            for dy in (0, 1):
                if 0 <= px + dx < size and 0 <= py + dy < size:
                    i = ((py + dy) * size + px + dx) * 3
                    pix[i:i + 3] = bytes(rgb)
    for (ax, ay), (bx, by) in zip(programmed, programmed[1:]):
        n = max(2, int(math.hypot(bx - ax, by - ay) * scale))
        for k in range(n + 1):
            plot(ax + (bx - ax) * k / n, ay + (by - ay) * k / n, (150, 170, 230))
    for x, y in sampled:
        plot(x, y, (200, 20, 20))
    write_png(path, size, size, pix)


def bar(done, total, t, est, tty):
    frac = min(1.0, done / total) if total else 0
    text = "[%-30s] %3d%%  line %3d/%d  %5.1f s / ~%4.1f s" % ("#" * int(30 * frac), frac * 100, done, total, t, est)
    if tty:
        sys.stdout.write("\r" + text)
        sys.stdout.flush()
    return text


def main():
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ngc = os.path.join(top, "configs", "demo", "demo.ngc")
    png = sys.argv[1] if len(sys.argv) > 1 else "demo-toolpath.png"
    wait_ready()
    s.poll()
    print("machine up: %s, %d joints, %s" % (os.path.basename(s.ini_filename), s.joints,
                                             "mm" if abs(s.linear_units - 1) < 1e-9 else "inch"))
    c.state(linuxcnc.STATE_ESTOP_RESET)
    c.state(linuxcnc.STATE_ON)
    c.mode(linuxcnc.MODE_MANUAL)
    c.home(-1)
    wait(lambda: all(s.homed[:s.joints]), 20, "homing")
    print("homed; running %s at 500%% feed override" % os.path.relpath(ngc, top))
    c.mode(linuxcnc.MODE_AUTO)
    c.wait_complete()
    c.feedrate(5.0)
    c.program_open(ngc)
    total = sum(1 for _ in open(ngc))
    tty = sys.stdout.isatty()
    start = time.time()
    c.auto(linuxcnc.AUTO_RUN, 0)
    samples, tools, last_tool, ferr = [], 0, None, 0.0
    est = 0.0
    next_bar = 0
    while True:
        s.poll()
        t = time.time() - start
        off = [s.g5x_offset[i] + s.g92_offset[i] + s.tool_offset[i] for i in range(3)]
        samples.append((s.actual_position[0] - off[0], s.actual_position[1] - off[1], s.actual_position[2] - off[2]))
        if s.tool_in_spindle != last_tool:
            tools += last_tool is not None
            last_tool = s.tool_in_spindle
        ferr = max([ferr] + [abs(s.joint[j]["ferror_current"]) for j in range(s.joints)])
        line = s.motion_line or s.current_line
        est = t * total / line if line else 0.0
        if t >= next_bar:
            text = bar(line, total, t, est, tty)
            if not tty:
                print(text)
            next_bar = t + (0.1 if tty else 2.0)
        if s.interp_state == linuxcnc.INTERP_IDLE and t > 0.2:
            break
        if t > 50:
            sys.exit("\ndemo: the program did not finish in 50 s")
        time.sleep(0.004)
    cycle = time.time() - start
    text = bar(total, total, cycle, cycle, tty)
    print("" if tty else text)
    errors = []
    while True:
        m = e.poll()
        if not m:
            break
        errors.append(m[1])
    programmed = programmed_path(ngc, os.path.join(top, "configs", "demo", "demo.tbl"))
    cut = [(x, y) for x, y, z in samples if z < 0.5]
    dev = max((distance_to_path(p, programmed) for p in cut[::5]), default=0.0)
    draw(png, programmed, [(x, y) for x, y, _ in samples])
    print("report:")
    print("  cycle time          %.2f s (program %d lines, %d position samples)" % (cycle, total, len(samples)))
    print("  tool changes        %d (tool %d in the spindle at the end)" % (tools, s.tool_in_spindle))
    print("  max following error %.4f mm" % ferr)
    print("  path deviation      %.3f mm (sampled points below Z0.5 from the programmed path)" % dev)
    print("  operator messages   %s" % ("; ".join(errors) if errors else "none"))
    print("  toolpath            %s (red: sampled, blue: programmed)" % png)
    return 0 if not errors else 1


if __name__ == "__main__":
    sys.exit(main())
