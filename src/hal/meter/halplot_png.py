"""halplot_png.py: draws sampled traces and writes them as a PNG (zlib only, no dependencies)."""
import os
import struct
import zlib

BACKGROUND = (255, 255, 255)
GRID = (220, 220, 220)
COLORS = ((200, 0, 0), (0, 120, 0), (0, 0, 200), (180, 120, 0), (140, 0, 160), (0, 140, 160))


class Canvas:
    """An RGB pixel buffer."""

    def __init__(self, width, height):
        self.width = width
        self.height = height
        self.rows = [bytearray(BACKGROUND * width) for _ in range(height)]

    def dot(self, x, y, color):
        """Set one pixel, ignoring points outside the canvas."""
        if 0 <= x < self.width and 0 <= y < self.height:
            self.rows[y][3 * x:3 * x + 3] = bytes(color)

    def hline(self, y, color):
        """Horizontal line across the whole canvas."""
        for x in range(self.width):
            self.dot(x, y, color)

    def line(self, x0, y0, x1, y1, color):
        """Straight line between two points (Bresenham)."""
        dx, dy = abs(x1 - x0), -abs(y1 - y0)
        sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
        err = dx + dy
        while True:
            self.dot(x0, y0, color)
            if x0 == x1 and y0 == y1:
                return
            e2 = 2 * err
            if e2 >= dy:
                err += dy
                x0 += sx
            if e2 <= dx:
                err += dx
                y0 += sy


def _chunk(kind, data):
    """One PNG chunk with its CRC."""
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png_bytes(canvas):
    """Encode a canvas as an 8-bit RGB PNG."""
    header = struct.pack(">IIBBBBB", canvas.width, canvas.height, 8, 2, 0, 0, 0)
    raw = b"".join(b"\x00" + bytes(row) for row in canvas.rows)
    return (b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header)
            + _chunk(b"IDAT", zlib.compress(raw, 9)) + _chunk(b"IEND", b""))


def _band_y(value, low, high, top, band):
    """Pixel row of a value inside a trace band (margin of 4 px)."""
    if high == low:
        return top + band // 2
    frac = (value - low) / (high - low)
    return top + 4 + int(round((1.0 - frac) * (band - 9)))


def draw_traces(traces, width=640, band=80):
    """Canvas with one band per trace (list of float lists), each scaled to its range."""
    canvas = Canvas(width, band * max(1, len(traces)))
    for index, values in enumerate(traces):
        top = index * band
        canvas.hline(top + band - 1, GRID)
        if not values:
            continue
        low, high = min(values), max(values)
        color = COLORS[index % len(COLORS)]
        step = (width - 1) / max(1, len(values) - 1)
        points = [(int(round(i * step)), _band_y(v, low, high, top, band))
                  for i, v in enumerate(values)]
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            canvas.line(x0, y0, x1, y0, color)
            canvas.line(x1, y0, x1, y1, color)
        if len(points) == 1:
            canvas.line(0, points[0][1], width - 1, points[0][1], color)
    return canvas


def write_png(path, traces):
    """Write the traces as a PNG file (via a temporary file and rename)."""
    tmp = path + ".tmp"
    with open(tmp, "wb") as out:
        out.write(png_bytes(draw_traces(traces)))
    os.replace(tmp, path)
