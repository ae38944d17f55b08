#!/usr/bin/env python3
"""speed-picture.py: draw servo traces (tp_bench trace output) as toolpaths coloured by speed.

Usage: speed-picture.py OUT.png TRACE [TRACE...]

Each TRACE file holds "x y z speed" per servo cycle; every trace gets a panel of its own, side by
side, all on one scale: blue at rest, through cyan, green and yellow, to red at the highest speed of
all traces.  A colour bar runs along the bottom.  Only the Python standard library is used.
"""
import struct
import sys
import zlib

PANEL = 560          # panel size in pixels
MARGIN = 20
BAR = 18             # colour bar height


def colour(f):
    """Speed fraction 0..1 to RGB: blue, cyan, green, yellow, red."""
    stops = [(0.0, (30, 60, 220)), (0.25, (0, 200, 220)), (0.5, (40, 190, 60)),
             (0.75, (240, 210, 0)), (1.0, (220, 30, 30))]
    f = min(1.0, max(0.0, f))
    for (f0, c0), (f1, c1) in zip(stops, stops[1:]):
        if f <= f1:
            t = (f - f0) / (f1 - f0)
            return tuple(int(a + (b - a) * t) for a, b in zip(c0, c1))
    return stops[-1][1]


def read_trace(path):
    pts = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) >= 4:
                pts.append((float(parts[0]), float(parts[1]), float(parts[3])))
    if not pts:
        sys.exit("speed-picture.py: %s: no samples" % path)
    return pts


def write_png(path, width, height, pixels):
    """pixels: bytearray of RGB rows."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        raw += pixels[y * width * 3:(y + 1) * width * 3]

    def chunk(tag, data):
        body = tag + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xffffffff)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    import os
    os.replace(tmp, path)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    traces = [read_trace(p) for p in sys.argv[2:]]
    vmax = max(max(v for _, _, v in t) for t in traces) or 1.0
    xs = [x for t in traces for x, _, _ in t]
    ys = [y for t in traces for _, y, _ in t]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    scale = (PANEL - 2 * MARGIN) / max(x1 - x0, y1 - y0, 1e-9)
    width = PANEL * len(traces)
    height = PANEL + BAR + MARGIN
    px = bytearray([255]) * (width * height * 3)

    def dot(cx, cy, rgb):
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                x, y = cx + dx, cy + dy
                if 0 <= x < width and 0 <= y < height:
                    i = (y * width + x) * 3
                    px[i:i + 3] = bytes(rgb)

    for n, t in enumerate(traces):
        ox = n * PANEL + MARGIN
        for x, y, v in t:
            cx = ox + int((x - x0) * scale)
            cy = PANEL - MARGIN - int((y - y0) * scale)
            dot(cx, cy, colour(v / vmax))
    for x in range(MARGIN, width - MARGIN):
        rgb = bytes(colour((x - MARGIN) / (width - 2 * MARGIN - 1)))
        for y in range(PANEL, PANEL + BAR):
            i = (y * width + x) * 3
            px[i:i + 3] = rgb
    write_png(sys.argv[1], width, height, px)
    print("speed-picture.py: %s: %d panels, speed scale 0 to %.1f units/s" % (sys.argv[1], len(traces), vmax))


main()
