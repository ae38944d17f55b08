component raster "Laser power along a raster line, from a program received through a HAL port";
pin in port program "Raster programs: text of the form PPU;OFFSET;BPP;COUNT;HEXDATA, one after the other";
pin in float position "Position of the laser along the raster axis, in machine units";
pin in bit reset "Rising edge: drop the program, clear any fault and discard unread port bytes; while TRUE nothing is read";
pin in bit enable "Output is forced to 0 while FALSE; loading and position tracking go on";
pin out float output "Laser power of the pixel under the laser, 0 to 100 (percent of full scale)";
pin out s32 state "0 waiting for or loading a program, 1 running, 2 pass finished, 3 fault";
pin out bit run "TRUE while a loaded program is being followed (state 1)";
pin out bit fault "TRUE while in the fault state (3)";
pin out s32 fault_code "Why the last program was refused: 0 none, 1 pixels-per-unit, 2 offset, 3 bits-per-pixel, 4 pixel count, 5 pixel data";
pin out s32 current_pixel "Index of the pixel under the laser, -1 outside the raster line";
variable int st;
variable int field;
variable char text[32];
variable int text_len;
variable double ppu;
variable double offset;
variable int bpp;
variable int npixels;
variable int nread;
variable unsigned acc;
variable int acc_bits;
variable int entered;
variable int last_reset;
variable unsigned short pixel[8192];
function _ "Read program bytes, follow the position and set the outputs";
description """
A raster program describes one line of pixels along an axis. It is written by
a user program (for example a G-code remap in Python) into the port signal
connected to program, as ASCII text:

    PPU;OFFSET;BPP;COUNT;HEXDATA

PPU is the number of pixels per machine unit (a decimal number above 0), OFFSET
the position where pixel 0 starts (a decimal number, sign allowed), BPP the bits
per pixel (1 to 16) and COUNT the number of pixels (1 to 8192). HEXDATA is a bit
stream written as hexadecimal digits (either case), most significant bit first:
pixel i is held in bits i*BPP to (i+1)*BPP-1, and the bits after the last pixel
up to the end of the last digit are padding. So exactly ceil(COUNT*BPP/4) digits
follow the header and the program ends with the last of them; the next program
may follow right away. Whitespace is accepted only between programs.

Bytes are taken from the port as they arrive, at most 1024 per period, so a
program may be written in pieces and the function never waits. Once every pixel
is read the program runs (state 1): pixel i covers positions from
OFFSET+i/PPU up to OFFSET+(i+1)/PPU, and output is the value of the
pixel under position scaled to 0..100 (the largest BPP-bit value gives
100), or 0 when enable is FALSE or the position is outside the line.
Because pixels are looked up by position, the same program serves a forward
pass (position increasing) and a reverse pass (position decreasing). When the
position leaves the line after having been on it, the pass is finished
(state 2) and the next program is read from the port.

A malformed program puts the component in the fault state (3): fault is
TRUE, fault-code says which part was wrong, output is 0 and nothing
more is read until a rising edge of reset, which also discards the rest
of the port contents. Nothing is printed from the realtime function.
""";
license "GPL";
author "OpenEMC";
;;
#define RASTER_MAX_PIXELS 8192
#define RASTER_CHUNK 256
#define RASTER_CHUNKS_PER_PERIOD 4
#define RASTER_IDLE 0
#define RASTER_RUN 1
#define RASTER_FINISHED 2
#define RASTER_FAULT 3
#define RASTER_DATA_FIELD 4

/* Parse an optionally signed decimal number ("-1.25", "3", ".5"); 0 on success. */
static int parse_decimal(const char *s, double *out)
{
    double value = 0, divisor = 1;
    int neg = 0, digits = 0, point = 0;
    if (*s == '+' || *s == '-') neg = *s++ == '-';
    for (; *s; s++) {
        if (*s == '.' && !point) {
            point = 1;
        } else if (*s >= '0' && *s <= '9') {
            digits++;
            value = value * 10 + (*s - '0');
            if (point) divisor *= 10;
        } else {
            return -1;
        }
    }
    if (!digits) return -1;
    *out = (neg ? -value : value) / divisor;
    return 0;
}

/* Parse an unsigned decimal integer no larger than max; 0 on success. */
static int parse_count(const char *s, int max, int *out)
{
    long value = 0;
    if (!*s) return -1;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return -1;
        value = value * 10 + (*s - '0');
        if (value > max) return -1;
    }
    *out = (int)value;
    return 0;
}

/* Value of a hexadecimal digit, -1 for any other byte. */
static int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* Forget the program being read or run and start a fresh parse. */
static void clear_program(struct __comp_state *__comp_inst)
{
    field = 0;
    text_len = 0;
    nread = 0;
    acc = 0;
    acc_bits = 0;
    entered = 0;
}

/* Enter the fault state with the given code. */
static void set_fault(struct __comp_state *__comp_inst, int code)
{
    clear_program(__comp_inst);
    st = RASTER_FAULT;
    fault_code = code;
}

/* Check and store header field `field` from the text buffer; a fault code or 0. */
static int take_field(struct __comp_state *__comp_inst)
{
    text[text_len] = 0;
    text_len = 0;
    switch (field) {
    case 0:
        return parse_decimal(text, &ppu) || !(ppu > 0) ? 1 : 0;
    case 1:
        return parse_decimal(text, &offset) ? 2 : 0;
    case 2:
        return parse_count(text, 16, &bpp) || bpp < 1 ? 3 : 0;
    default:
        return parse_count(text, RASTER_MAX_PIXELS, &npixels) || npixels < 1 ? 4 : 0;
    }
}

/* Feed one header byte; a fault code or 0. */
static int header_byte(struct __comp_state *__comp_inst, char c)
{
    int code;
    if (c != ';') {
        if (text_len >= (int)sizeof(text) - 1) return field + 1;
        text[text_len++] = c;
        return 0;
    }
    code = take_field(__comp_inst);
    if (!code) field++;
    return code;
}

/* Feed one hex digit of pixel data; 5 for a non-hex byte, else 0. */
static int data_byte(struct __comp_state *__comp_inst, char c)
{
    int v = hex_value(c);
    unsigned mask = (1u << bpp) - 1;
    if (v < 0) return 5;
    acc = (acc << 4) | (unsigned)v;
    acc_bits += 4;
    while (acc_bits >= bpp && nread < npixels) {
        acc_bits -= bpp;
        pixel[nread++] = (unsigned short)((acc >> acc_bits) & mask);
    }
    acc &= (1u << acc_bits) - 1;
    if (nread == npixels) {
        clear_program(__comp_inst);
        st = RASTER_RUN;
    }
    return 0;
}

/* Parse up to n bytes; returns how many were consumed (stops at a program end or fault). */
static unsigned parse_bytes(struct __comp_state *__comp_inst, const char *buf, unsigned n)
{
    unsigned i;
    int code;
    for (i = 0; i < n && st != RASTER_RUN && st != RASTER_FAULT; i++) {
        char c = buf[i];
        if (field == 0 && text_len == 0 && (c == ' ' || c == '\t' || c == '\r' || c == '\n'))
            continue;
        st = RASTER_IDLE;
        code = field < RASTER_DATA_FIELD ? header_byte(__comp_inst, c) : data_byte(__comp_inst, c);
        if (code) set_fault(__comp_inst, code);
    }
    return i;
}

/* Take whatever program bytes the port holds, a bounded amount per period. */
static void read_program(struct __comp_state *__comp_inst)
{
    char buf[RASTER_CHUNK];
    int chunk;
    for (chunk = 0; chunk < RASTER_CHUNKS_PER_PERIOD; chunk++) {
        unsigned n = hal_port_readable(program);
        if (n > RASTER_CHUNK) n = RASTER_CHUNK;
        if (n == 0 || !hal_port_peek(program, buf, n)) return;
        hal_port_peek_commit(program, parse_bytes(__comp_inst, buf, n));
        if (st == RASTER_RUN || st == RASTER_FAULT) return;
    }
}

/* Follow the position along the loaded line; the pass ends when it leaves after entering. */
static void track_position(struct __comp_state *__comp_inst)
{
    double where = (position - offset) * ppu + 1e-9;
    int idx;
    if (where >= 0 && where < npixels) {
        idx = (int)where;
        entered = 1;
        current_pixel = idx;
        output = enable ? pixel[idx] * 100.0 / (double)((1u << bpp) - 1) : 0;
        return;
    }
    current_pixel = -1;
    output = 0;
    if (entered) {
        entered = 0;
        st = RASTER_FINISHED;
    }
}

/* Rising edge of reset: drop everything and empty the port. */
static void do_reset(struct __comp_state *__comp_inst)
{
    if (!last_reset) {
        hal_port_clear(program);
        clear_program(__comp_inst);
        fault_code = 0;
    }
    st = RASTER_IDLE;
}

/* One period: reset, load or follow, then publish the state pins. */
FUNCTION(_)
{
    current_pixel = -1;
    output = 0;
    if (reset) {
        do_reset(__comp_inst);
    } else if (st != RASTER_RUN && st != RASTER_FAULT) {
        read_program(__comp_inst);
    }
    last_reset = reset;
    if (st == RASTER_RUN && !reset) track_position(__comp_inst);
    state = st;
    run = st == RASTER_RUN;
    fault = st == RASTER_FAULT;
}
