component carousel "Bring a tool-changer carousel to a pocket, reading its position from one of several sensor encodings";
pin in s32 pocket_number "Pocket to go to, latched on the rising edge of enable; wrapped into 1..pockets so several tool numbers can share a pocket";
pin in bit enable "A rising edge starts a move to pocket-number; FALSE stops the motor and clears ready";
pin out bit active "TRUE while the carousel is homing, moving or pulsing in reverse";
pin out bit ready "TRUE once the pocket asked for by enable is in position, until enable goes FALSE";
pin in bit strobe = 1 "Absolute encodings (gray, binary, bcd, single) read the sense pins only while this is TRUE";
pin in bit parity_ "Parity bit of the position code (gray, binary, bcd); the code plus this bit must hold an even number of ones";
pin in bit sense-#[32 : personality] "Position sensors: code bits, least significant first (gray, binary, bcd); one per pocket (single); sense-0 index and sense-1 pocket sensor (index, edge); sense-0 index (counts)";
pin in float rev_pulse "Seconds of reverse drive after a forward arrival, to seat a ratchet carousel against its pawl; 0 disables";
pin in float fwd_dc "motor-vel while turning forward (pocket numbers increasing)";
pin in float rev_dc "Magnitude of motor-vel while turning in reverse (motor-vel is then negative)";
pin in float hold_dc "motor-vel while the carousel is not moving";
pin in float align_dc "Slow speed for the last pocket of a move; 0 keeps the full speed to the end";
pin in float decel_time "Seconds over which the speed falls from fwd-dc/rev-dc to align-dc once the target is the next pocket";
pin in float scale = 1 "Encoder counts per pocket (counts encoding)";
pin in s32 counts "Encoder position in counts (counts encoding)";
pin in bit jog_fwd "A rising edge while enable is FALSE moves one pocket forward";
pin in bit jog_rev "A rising edge while enable is FALSE moves one pocket in reverse (dir=2 only)";
pin out bit motor_fwd "TRUE to turn the carousel forward";
pin out bit motor_rev "TRUE to turn the carousel in reverse";
pin out float motor_vel "Signed speed or duty cycle for a DC motor driver or a velocity-mode stepgen";
pin out s32 current_position "Pocket at the change position, 0 while unknown or between pockets";
pin out bit homing "TRUE while searching for the index (index, edge and counts encodings)";
pin out bit homed "TRUE once the position is known: at once for absolute encodings, after the index was seen otherwise";
pin out bit parity_error "TRUE while the position code and parity bit hold an odd number of ones";
pin out s32 state "0 idle, 1 homing, 2 moving, 3 slowing for the last pocket, 4 reverse pulse, 5 in position";
variable int n_pockets;
variable int enc;
variable int bidir;
variable int pos;
variable int last_valid;
variable int target;
variable int step_dir;
variable int last_dir = 1;
variable int jog_step;
variable int by_jog;
variable int pocket_event;
variable int index_event;
variable int last_sense1;
variable int last_sense0;
variable int last_enable;
variable int last_jog_fwd;
variable int last_jog_rev;
variable int count_offset;
variable double target_count;
variable double timer;
function _ "Read the sensors, run the state machine and drive the motor outputs";
modparam dummy pockets "Number of pockets of each carousel, comma separated (at most 8 carousels); default one carousel of 8 pockets";
modparam dummy encoding "Position encoding of each carousel: gray, binary, bcd, index, edge, counts or single (default gray)";
modparam dummy num_sense "Number of sense pins of each gray, binary or bcd carousel (default 4); single uses one per pocket, index and edge two, counts one";
modparam dummy dir "1 for a carousel that only turns forward, 2 (default) for one that turns both ways, taking the shorter way";
option rtapi_app no;
option post_export yes;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
description """Each carousel N has pins carousel.N.* and a funct carousel.N for a floating-point thread.

Encodings: gray, binary and bcd read the pocket number from the sense
pins (code 0 or a code above the pocket count means "between pockets"); single has one
sensor per pocket; index counts rising edges of the pocket sensor sense-1 and
edge counts both of its edges, a pocket edge seen while the index sense-0 is TRUE being
pocket 1; counts divides the encoder count by scale, the rising edge of sense-0 marking
pocket 1. The last three home first: the carousel turns forward until the index is seen.

With dir=2 the carousel takes the shorter way (forward on a tie). When align-dc is not zero
the speed falls to it over decel-time once the target is the next pocket. After a forward
arrival rev-pulse seconds of reverse drive seat a ratchet carousel. jog-fwd and jog-rev move
one pocket while enable is FALSE; they do not set ready.

Bad module arguments (unknown encoding, dir other than 1 or 2, too few sense pins for the
pocket count, more entries than carousels) fail the load with a message. count= and names= are
not accepted: pockets= sets the number of carousels.""";
;;
#define CAROUSEL_MAX 8
#define ST_IDLE 0
#define ST_HOMING 1
#define ST_MOVING 2
#define ST_DECEL 3
#define ST_REV_PULSE 4
#define ST_IN_POSITION 5

enum { ENC_GRAY, ENC_BINARY, ENC_BCD, ENC_INDEX, ENC_EDGE, ENC_COUNTS, ENC_SINGLE, ENC_N };
static const char *enc_names[ENC_N] = { "gray", "binary", "bcd", "index", "edge", "counts", "single" };

static int pockets[CAROUSEL_MAX] = { [0 ... CAROUSEL_MAX - 1] = -1 };
RTAPI_MP_ARRAY_INT(pockets, CAROUSEL_MAX, "number of pockets of each carousel");
static char *encoding[CAROUSEL_MAX];
RTAPI_MP_ARRAY_STRING(encoding, CAROUSEL_MAX, "position encoding of each carousel");
static int num_sense[CAROUSEL_MAX] = { [0 ... CAROUSEL_MAX - 1] = -1 };
RTAPI_MP_ARRAY_INT(num_sense, CAROUSEL_MAX, "number of sense pins of each carousel");
static int dir[CAROUSEL_MAX] = { [0 ... CAROUSEL_MAX - 1] = -1 };
RTAPI_MP_ARRAY_INT(dir, CAROUSEL_MAX, "1 unidirectional, 2 bidirectional");

static int cfg_enc[CAROUSEL_MAX];
static int cfg_sense[CAROUSEL_MAX];

/* Wrap any pocket number into 1..n. */
static int wrap_pocket(long long p, int n)
{
    return (int)(((p - 1) % n + n) % n) + 1;
}

/* Largest value a bcd code of the given number of bits can hold. */
static long bcd_max(int bits)
{
    long max = 0, place = 1;
    while (bits > 0) {
        int b = bits < 4 ? bits : 4;
        int digit = (1 << b) - 1;
        max += (digit > 9 ? 9 : digit) * place;
        place *= 10;
        bits -= b;
    }
    return max;
}

/* Sense pin count used by carousel c with encoding e, or -1 after printing an error. */
static int sense_count(int c, int e)
{
    int n = pockets[c], ns = num_sense[c];
    if (e == ENC_INDEX || e == ENC_EDGE) return 2;
    if (e == ENC_COUNTS) return 1;
    if (e == ENC_SINGLE) {
        if (n > 32 || (ns != -1 && ns != n)) {
            rtapi_print_msg(RTAPI_MSG_ERR,
                            "carousel: carousel %d: single encoding needs one sense pin per pocket (at most 32)\n", c);
            return -1;
        }
        return n;
    }
    if (ns == -1) ns = 4;
    if (ns < 1 || ns > 32) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: carousel %d: num_sense=%d not in 1..32\n", c, ns);
        return -1;
    }
    if ((e == ENC_BCD ? bcd_max(ns) : (ns >= 31 ? 0x7fffffffL : (1L << ns) - 1)) < n) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: carousel %d: %d %s sense pins cannot number %d pockets\n",
                        c, ns, enc_names[e], n);
        return -1;
    }
    return ns;
}

/* Encoding number of carousel c, or -1 after printing an error. */
static int parse_encoding(int c)
{
    int e;
    if (!encoding[c] || !encoding[c][0]) return ENC_GRAY;
    for (e = 0; e < ENC_N; e++)
        if (!strcmp(encoding[c], enc_names[e])) return e;
    rtapi_print_msg(RTAPI_MSG_ERR,
                    "carousel: carousel %d: unknown encoding '%s' (gray, binary, bcd, index, edge, counts or single)\n",
                    c, encoding[c]);
    return -1;
}

/* Check that an array parameter has no more entries than there are carousels. */
static int check_extra(const char *name, int given)
{
    if (!given) return 0;
    rtapi_print_msg(RTAPI_MSG_ERR, "carousel: %s= has more entries than pockets=\n", name);
    return -EINVAL;
}

/* Validate the module parameters of carousel c and fill its configuration. */
static int check_carousel(int c)
{
    if (pockets[c] < 1 || pockets[c] > 1000) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: carousel %d: pockets=%d not in 1..1000\n", c, pockets[c]);
        return -EINVAL;
    }
    if (dir[c] == -1) dir[c] = 2;
    if (dir[c] != 1 && dir[c] != 2) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: carousel %d: dir=%d must be 1 or 2\n", c, dir[c]);
        return -EINVAL;
    }
    cfg_enc[c] = parse_encoding(c);
    if (cfg_enc[c] < 0) return -EINVAL;
    cfg_sense[c] = sense_count(c, cfg_enc[c]);
    return cfg_sense[c] < 0 ? -EINVAL : 0;
}

/* Validate every module parameter; returns the number of carousels or -EINVAL. */
static int check_params(void)
{
    int n = 0, c;
    if (pockets[0] == -1) pockets[0] = 8;
    while (n < CAROUSEL_MAX && pockets[n] != -1) n++;
    for (c = 0; c < n; c++)
        if (check_carousel(c)) return -EINVAL;
    for (c = n; c < CAROUSEL_MAX; c++) {
        if (check_extra("encoding", encoding[c] != 0) || check_extra("num_sense", num_sense[c] != -1) ||
            check_extra("dir", dir[c] != -1))
            return -EINVAL;
    }
    return n;
}

/* Copy the checked configuration into the new instance. */
POST_EXPORT()
{
    n_pockets = pockets[extra_arg];
    enc = cfg_enc[extra_arg];
    bidir = dir[extra_arg] == 2;
    homed = enc != ENC_INDEX && enc != ENC_EDGE && enc != ENC_COUNTS;
    return 0;
}

/* The sense pins as an integer, sense-0 the least significant bit. */
static unsigned sense_word(struct __comp_state *__comp_inst)
{
    unsigned w = 0;
    int i;
    for (i = 0; i < personality; i++)
        if (sense(i)) w |= 1u << i;
    return w;
}

/* Decode an absolute position code; 0 when it names no pocket. */
static int decode_code(struct __comp_state *__comp_inst, unsigned w)
{
    long v = 0, place = 1;
    unsigned s;
    if (enc == ENC_GRAY) {
        for (s = 1; s < 32; s <<= 1) w ^= w >> s;
        v = w;
    } else if (enc == ENC_BINARY) {
        v = w;
    } else {
        for (; w; w >>= 4, place *= 10) {
            if ((w & 15) > 9) return 0;
            v += (w & 15) * place;
        }
    }
    return v >= 1 && v <= n_pockets ? (int)v : 0;
}

/* Read an absolute encoding (gray, binary, bcd, single) while strobe is TRUE. */
static void read_absolute(struct __comp_state *__comp_inst)
{
    unsigned w;
    int i, ones = parity_;
    if (!strobe) return;
    w = sense_word(__comp_inst);
    if (enc == ENC_SINGLE) {
        pos = 0;
        for (i = 0; i < personality && !pos; i++)
            if (sense(i)) pos = i + 1;
        return;
    }
    for (i = 0; i < personality; i++) ones += (w >> i) & 1;
    parity_error = ones & 1;
    pos = decode_code(__comp_inst, w);
}

/* Count pocket-sensor edges (index, edge); the index marks pocket 1. */
static void read_incremental(struct __comp_state *__comp_inst)
{
    int s1 = sense(1);
    int d = step_dir ? step_dir : last_dir;
    pocket_event = enc == ENC_INDEX ? (s1 && !last_sense1) : (s1 != last_sense1);
    last_sense1 = s1;
    index_event = pocket_event && sense(0);
    if (index_event) {
        pos = 1;
        homed = 1;
    } else if (pocket_event && homed) {
        pos = wrap_pocket(pos + d, n_pockets);
    }
}

/* Unwrapped pocket index (0 = pocket 1) of the encoder count, bounded against a silly scale. */
static long long count_index(struct __comp_state *__comp_inst)
{
    double sc = scale > 0 ? scale : 1.0;
    double q = floor(((double)counts - count_offset) / sc + 0.5);
    return fabs(q) < 1e15 ? (long long)q : 0;
}

/* Pocket from the encoder count (counts); the index rising edge marks pocket 1. */
static void read_counts(struct __comp_state *__comp_inst)
{
    index_event = sense(0) && !last_sense0;
    last_sense0 = sense(0);
    if (index_event && state == ST_HOMING) {
        count_offset = counts;
        homed = 1;
    }
    if (homed) pos = wrap_pocket(count_index(__comp_inst) + 1, n_pockets);
}

/* Update pos and current-position from the sensors. */
static void read_position(struct __comp_state *__comp_inst)
{
    index_event = 0;
    pocket_event = 0;
    if (enc == ENC_INDEX || enc == ENC_EDGE) read_incremental(__comp_inst);
    else if (enc == ENC_COUNTS) read_counts(__comp_inst);
    else read_absolute(__comp_inst);
    if (pos) last_valid = pos;
    current_position = pos;
}

/* Direction from p to target: +1 or -1 (shorter way when bidirectional). */
static int choose_dir(struct __comp_state *__comp_inst, int p)
{
    int ahead = ((target - p) % n_pockets + n_pockets) % n_pockets;
    if (!bidir) return 1;
    return ahead <= n_pockets / 2 ? 1 : -1;
}

/* Stop at the target: reverse pulse after a forward arrival, then rest. */
static void arrive(struct __comp_state *__comp_inst)
{
    if (rev_pulse > 0 && step_dir > 0) {
        state = ST_REV_PULSE;
        timer = 0;
        return;
    }
    if (step_dir) last_dir = step_dir;
    step_dir = 0;
    state = by_jog ? ST_IDLE : ST_IN_POSITION;
    ready = !by_jog;
    by_jog = 0;
}

/* Set the target count of a move in counts mode, step_dir already chosen. */
static void set_target_count(struct __comp_state *__comp_inst)
{
    double sc = scale > 0 ? scale : 1.0;
    long long here = count_index(__comp_inst);
    int ahead = ((target - pos) % n_pockets + n_pockets) % n_pockets;
    int steps = step_dir > 0 ? ahead : ahead - n_pockets;
    target_count = count_offset + (here + steps) * sc;
}

/* Start the move to target (or to pos + jog_step) from a known position. */
static void begin_move(struct __comp_state *__comp_inst)
{
    int base = pos ? pos : last_valid;
    if (jog_step) {
        if (!base) { state = ST_IDLE; by_jog = 0; jog_step = 0; return; }
        target = wrap_pocket(base + jog_step, n_pockets);
        step_dir = jog_step;
        jog_step = 0;
    } else {
        step_dir = base ? choose_dir(__comp_inst, base) : 1;
    }
    if (pos == target) {
        step_dir = 0;
        arrive(__comp_inst);
        return;
    }
    state = ST_MOVING;
    timer = 0;
    if (enc == ENC_COUNTS) set_target_count(__comp_inst);
}

/* Begin a command: home first when the position is not known yet. */
static void begin_command(struct __comp_state *__comp_inst)
{
    ready = 0;
    if (!homed) {
        state = ST_HOMING;
        step_dir = 1;
        return;
    }
    begin_move(__comp_inst);
}

/* React to edges of enable, jog-fwd and jog-rev. */
static void read_commands(struct __comp_state *__comp_inst)
{
    int rise_fwd = jog_fwd && !last_jog_fwd, rise_rev = jog_rev && !last_jog_rev;
    last_jog_fwd = jog_fwd;
    last_jog_rev = jog_rev;
    if (enable && !last_enable) {
        target = wrap_pocket(pocket_number, n_pockets);
        by_jog = 0;
        jog_step = 0;
        begin_command(__comp_inst);
    } else if (!enable && last_enable) {
        state = ST_IDLE;
        ready = 0;
        by_jog = 0;
        jog_step = 0;
        step_dir = 0;
    } else if (!enable && (state == ST_IDLE || state == ST_IN_POSITION)
               && (rise_fwd || (rise_rev && bidir))) {
        by_jog = 1;
        jog_step = rise_fwd ? 1 : -1;
        begin_command(__comp_inst);
    }
    last_enable = enable;
}

/* TRUE when the carousel has reached its target this cycle. */
static int at_target(struct __comp_state *__comp_inst)
{
    if (enc == ENC_COUNTS)
        return step_dir > 0 ? counts >= target_count : counts <= target_count;
    if (enc == ENC_INDEX || enc == ENC_EDGE) return pocket_event && pos == target;
    return pos == target;
}

/* TRUE when the target is the next pocket in the direction of travel. */
static int near_target(struct __comp_state *__comp_inst)
{
    double sc = scale > 0 ? scale : 1.0;
    if (enc == ENC_COUNTS) return fabs(target_count - counts) <= sc;
    return pos && wrap_pocket(pos + step_dir, n_pockets) == target;
}

/* One cycle of the moving states. */
static void run_move(struct __comp_state *__comp_inst, double dt)
{
    if (state == ST_HOMING) {
        if (index_event) begin_move(__comp_inst);
        return;
    }
    if (enc != ENC_COUNTS && enc != ENC_INDEX && enc != ENC_EDGE && pos && pos != target)
        step_dir = choose_dir(__comp_inst, pos);
    if (at_target(__comp_inst)) {
        arrive(__comp_inst);
        return;
    }
    if (state == ST_DECEL) timer += dt;
    else if (align_dc != 0 && near_target(__comp_inst)) {
        state = ST_DECEL;
        timer = 0;
    }
}

/* One cycle of the reverse pulse. */
static void run_rev_pulse(struct __comp_state *__comp_inst, double dt)
{
    timer += dt;
    if (timer < rev_pulse) return;
    last_dir = 1;
    step_dir = 0;
    state = by_jog ? ST_IDLE : ST_IN_POSITION;
    ready = !by_jog;
    by_jog = 0;
}

/* Speed magnitude of a move: full, or ramping down to align-dc. */
static double move_speed(struct __comp_state *__comp_inst)
{
    double full = fabs(step_dir > 0 ? fwd_dc : rev_dc), slow = fabs(align_dc), f;
    if (state != ST_DECEL) return full;
    f = decel_time > 0 ? timer / decel_time : 1.0;
    if (f > 1.0) f = 1.0;
    return full + (slow - full) * f;
}

/* Set the motor outputs for the current state. */
static void drive(struct __comp_state *__comp_inst)
{
    int moving = state == ST_HOMING || state == ST_MOVING || state == ST_DECEL;
    active = moving || state == ST_REV_PULSE;
    homing = state == ST_HOMING;
    if (state == ST_REV_PULSE) {
        motor_fwd = 0;
        motor_rev = 1;
        motor_vel = -fabs(rev_dc);
    } else if (moving) {
        motor_fwd = step_dir > 0;
        motor_rev = step_dir < 0;
        motor_vel = step_dir > 0 ? move_speed(__comp_inst) : -move_speed(__comp_inst);
    } else {
        motor_fwd = 0;
        motor_rev = 0;
        motor_vel = hold_dc;
    }
}

/* Funct carousel.N: sensors, commands, state machine, motor outputs. */
FUNCTION(_)
{
    read_position(__comp_inst);
    read_commands(__comp_inst);
    if (state == ST_HOMING || state == ST_MOVING || state == ST_DECEL)
        run_move(__comp_inst, fperiod);
    else if (state == ST_REV_PULSE)
        run_rev_pulse(__comp_inst, fperiod);
    drive(__comp_inst);
}

/* Create the configured carousels. */
int rtapi_app_main(void)
{
    int c, n = check_params(), r = 0;
    char buf[HAL_NAME_LEN + 1];
    if (n < 0) return n;
    comp_id = hal_init("carousel");
    if (comp_id < 0) return comp_id;
    for (c = 0; c < n && r == 0; c++) {
        rtapi_snprintf(buf, sizeof(buf), "carousel.%d", c);
        r = export(buf, c, cfg_sense[c]);
    }
    if (r) {
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Remove the component. */
void rtapi_app_exit(void)
{
    hal_exit(comp_id);
}
