component raster "Laser power along a raster line, from a program received through a HAL port";
pin in port program "Raster program: offset;bpp;ppu;count;pixels (see the description)";
pin in float position "Position of the laser along the raster axis, in machine units";
pin in bit run "TRUE starts the program waiting in the port and keeps it running; FALSE ends it";
pin in bit reset "TRUE: back to idle, fault cleared, the port emptied";
pin out float output = -1 "Laser power in percent, -1 for off";
pin out bit enabled "TRUE while a program runs";
pin out s32 state "0 idle, 1 running, 2 fault";
pin out bit fault "TRUE in the fault state (from the period after the fault)";
pin out s32 fault_code "0 none, 1 invalid offset, 2 invalid bpp, 3 invalid ppu, 4 invalid count, 5 bad pixel data, 6 program size mismatch";
pin out float program_offset "offset of the running program";
pin out s32 bpp "Bits per pixel of the running program";
pin out float ppu "Pixels per machine unit of the running program";
pin out s32 count_ "Pixels of the running program";
pin out float program_position "position when the program started";
pin out float bitmap_position "Position along the line in pixels";
pin out s32 current_pixel_index = -1 "Index of the last pixel read";
pin out float current_pixel_value = -1 "Value of the last pixel read (percent, -1 off)";
pin out float previous_pixel_value = -1 "Value of the pixel before it";
pin out float fraction "Interpolation fraction between the previous and the current pixel";
function _ "Start, follow and end the raster program";
include <rtapi_math.h>;
include "raster_parse.h";
license "GPL";
author "OpenEMC";
description """
LinuxCNC's raster. A raster program describes one line of pixels along an axis;
a user program (for example the Python raster module) writes it into the port
signal connected to program, as ASCII text, before setting run:

    offset;bpp;ppu;count;pixels

offset (a number) is where the line starts relative to the position when run
rises; a negative offset means the line is swept from positive to negative. bpp,
the bits per pixel, is 4, 8, ... or 32; each pixel is bpp/4 hexadecimal digits.
ppu (above 0) is pixels per machine unit and count (at least 2) the number of
pixels; exactly count*bpp/4 hex digits follow, without separators. A pixel of all
ones (F, FF, ...) means laser off (output -1); any other value v is
100*v/(2^bpp - 2) percent, so E is 100 percent at 4 bits per pixel.

When run rises the header is checked (fault codes 1 offset, 2 bpp, 3 ppu,
4 count) and the rest of the port must be exactly the pixel data (6); then
the program runs: pixel k sits k/ppu from the start of the line, and output is
the pixel's value when the position is on a pixel, the linear interpolation
between two neighbouring pixels that are both on, or -1 (off) elsewhere. Bad
pixel data faults with code 5. run FALSE ends the program and empties the port;
a fault holds (output -1) until reset. While reset is TRUE the component stays
idle and the port empty (run does not start a program then).
""";
;;
#define RASTER_IDLE 0
#define RASTER_RUN 1
#define RASTER_FAULT 2
#define RASTER_FLOAT_PEEK 32
#define RASTER_INT_PEEK 10
#define RASTER_EPS 1e-4

/* Peek up to max bytes of the next header field; the field's length before ';' or -1 without one. */
static int peek_field(const hal_port_t *port, char *buf, int max, int *got)
{
    unsigned avail = hal_port_readable(port);
    int n = avail < (unsigned)max ? (int)avail : max;
    *got = 0;
    if (n <= 0 || !hal_port_peek(port, buf, n)) return -1;
    *got = n;
    for (int i = 0; i < n; i++)
        if (buf[i] == ';') return i;
    return -1;
}

/* Read a float header field; 0 or -1. */
static int read_float(const hal_port_t *port, double *v)
{
    char buf[RASTER_FLOAT_PEEK];
    int got, len;
    if (peek_field(port, buf, RASTER_FLOAT_PEEK, &got) < 0) return -1;
    len = raster_number(buf, got, v);
    if (len == 0 || len + 1 > got) return -1;
    return hal_port_peek_commit(port, len + 1) ? 0 : -1;
}

/* Read an integer header field; 0 or -1. */
static int read_int(const hal_port_t *port, long *v)
{
    char buf[RASTER_INT_PEEK];
    int got, len;
    if (peek_field(port, buf, RASTER_INT_PEEK, &got) < 0) return -1;
    len = raster_integer(buf, got, v);
    if (len == 0 || len + 1 > got) return -1;
    return hal_port_peek_commit(port, len + 1) ? 0 : -1;
}

/* Parse the header and check the data size; 0 or the fault code. */
static int parse_header(struct __comp_state *__comp_inst)
{
    double off, p;
    long b, c;
    if (read_float(program, &off)) return 1;
    program_offset = off;
    if (read_int(program, &b) || b <= 0 || b > 32 || b % 4) return 2;
    bpp = (int)b;
    if (read_float(program, &p) || !(p > 0)) return 3;
    ppu = p;
    if (read_int(program, &c) || c < 2) return 4;
    count_ = (int)(c > 0x7fffffffL ? 0x7fffffffL : c);
    if ((long long)hal_port_readable(program) != (long long)(bpp / 4) * c) return 6;
    return 0;
}

/* The next pixel's value (percent, -1 off) into *v; -1 on unreadable or bad hex data. */
static int read_pixel(struct __comp_state *__comp_inst, double *v)
{
    char buf[8];
    int n = bpp / 4;
    unsigned long long x = 0, off = (1ULL << bpp) - 1;
    if (!hal_port_read(program, buf, n)) return -1;
    for (int i = 0; i < n; i++) {
        int d = raster_hex(buf[i]);
        if (d < 0) return -1;
        x = (x << 4) | (unsigned)d;
    }
    *v = x == off ? -1.0 : 100.0 * (double)x / (double)(off - 1);
    return 0;
}

/* IDLE: clear the line outputs; start a program when run is TRUE. */
static void st_idle(struct __comp_state *__comp_inst)
{
    bitmap_position = 0;
    current_pixel_value = -1;
    previous_pixel_value = -1;
    current_pixel_index = -1;
    if (!run) return;
    int code = parse_header(__comp_inst);
    if (code) {
        fault_code = code;
        state = RASTER_FAULT;
        return;
    }
    program_position = position;
    state = RASTER_RUN;
}

/* RUN: read pixels up to the position and set the output. */
static void st_run(struct __comp_state *__comp_inst)
{
    double bmp = (position - (program_position + program_offset)) * ppu * (program_offset < 0 ? -1 : 1) + 0.0, v;
    bitmap_position = bmp;
    if (!run) {
        state = RASTER_IDLE;
        hal_port_clear(program);
        return;
    }
    enabled = 1;
    while (current_pixel_index < count_ - 1 && current_pixel_index < bmp) {
        current_pixel_index++;
        previous_pixel_value = current_pixel_value;
        if (read_pixel(__comp_inst, &v)) {
            fault_code = 5;
            state = RASTER_FAULT;
            return;
        }
        current_pixel_value = v;
    }
    int k = current_pixel_index;
    if (fabs(bmp - k) < RASTER_EPS) {
        output = current_pixel_value;
    } else if (fabs(bmp - (k - 1)) < RASTER_EPS) {
        output = previous_pixel_value;
    } else if (bmp > k - 1 && bmp < k && previous_pixel_value >= 0 && current_pixel_value >= 0) {
        fraction = bmp - (k - 1);
        output = previous_pixel_value + fraction * (current_pixel_value - previous_pixel_value);
    }
}

FUNCTION(_)
{
    output = -1;
    enabled = 0;
    if (reset) {
        state = RASTER_IDLE;
        fault = 0;
        fault_code = 0;
        hal_port_clear(program);
        bitmap_position = 0;
        current_pixel_value = -1;
        previous_pixel_value = -1;
        current_pixel_index = -1;
        return;
    }
    if (state == RASTER_FAULT) fault = 1;
    else if (state == RASTER_IDLE) st_idle(__comp_inst);
    else st_run(__comp_inst);
}
