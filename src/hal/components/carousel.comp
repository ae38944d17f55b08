component carousel "Bring a tool-changer carousel to a pocket, reading its position from one of several sensor encodings";
pin in s32 pocket_number "Pocket to go to; wrapped into 1..pockets so several tool numbers can share a pocket";
pin in bit enable "TRUE starts a move to pocket-number; FALSE during a move stops it";
pin out bit active "TRUE while the carousel is moving or homing";
pin out bit ready "TRUE once the pocket is in position (stays TRUE after enable drops, until the next move)";
pin in bit strobe = TRUE "current-position and parity-error are updated only while this is TRUE";
pin in bit parity_ "Parity bit of the position code (gray, binary, bcd)";
pin in bit sense-#[32 : personality] "Position sensors (see the description)";
pin in float rev_pulse "Seconds of reverse drive after arrival, to seat a ratchet carousel; 0 disables";
pin in float fwd_dc "motor-vel while turning forward";
pin in float rev_dc "motor-vel while turning in reverse";
pin in float hold_dc "motor-vel while the carousel is stopped";
pin in float align_dc "Speed of the slow final alignment move; 0 skips it";
pin in float decel_time "Seconds of coasting (motor-vel 0) after arrival before the alignment move";
pin in s32 counts "Encoder position in counts (counts encoding)";
pin out float counts_target "Position for a position-mode stepgen or PID in counts";
pin io bit index_enable "Connect to the encoder's index-enable (counts encoding homing)";
pin in s32 scale = 100 "Encoder counts per pocket (counts encoding)";
pin in s32 width = 10 "Width in counts of the window around each pocket position (counts encoding)";
pin in s32 home_offset "Counts from the index to pocket 1 (counts encoding)";
pin in bit jog_fwd "Move one pocket forward while enable is FALSE";
pin in bit jog_rev "Move one pocket in reverse while enable is FALSE (bidirectional changers)";
pin out bit motor_fwd "TRUE to turn the carousel forward";
pin out bit motor_rev "TRUE to turn the carousel in reverse";
pin out float motor_vel "fwd-dc, rev-dc, align-dc, hold-dc or 0, for a DC motor driver or a velocity-mode stepgen";
pin out s32 current_position "Pocket at the change position";
pin out bit homed "TRUE once the position is known (absolute encodings: from the first period)";
pin in bit unhome "A rising edge clears homed";
pin out bit parity_error "TRUE when the code's parity does not match the parity module argument XOR the parity pin";
param r s32 state "0 waiting, 1 choosing a direction, 2 moving, 3 reverse pulse, 5 coasting, 6 backing up to the index, 7 backing off it, 8 final move, 9 waiting for enable FALSE, 10 and 11 homing, 20 jogging";
param r s32 target "Pocket being moved to";
param r float timer "Time left in the timed states";
param r bit homing "TRUE while homing";
param r s32 motor_dir "1 forward, -1 reverse, 0 waiting";
param r s32 base_counts "counts at pocket 1 (counts encoding)";
param r s32 counts_offset "Not used (LinuxCNC compatibility)";
param rw u32 debounce "Periods the position must stay at the target before the move counts as done";
variable int n_pockets;
variable int enc;
variable int bidir;
variable int parity_arg;
variable int debounce_left;
variable int index_mem;
variable int unhome_mem;
variable int fail_told;
variable int started;
function _ "Read the sensors, run the state machine and drive the motor outputs";
modparam dummy pockets "Pockets of each carousel (at most 8 carousels; the list ends at the first 0; default 8)";
modparam dummy encoding "Encoding of each carousel: gray (default), binary, bcd, single, index, edge or counts";
modparam dummy num_sense "Sense pins of each carousel (default 4; index always 2, single at least one per pocket)";
modparam dummy dir "1 turns only forward, 2 (default) both ways, the shorter way";
modparam dummy parity "Parity of each carousel's position code: 0 even (default), 1 odd";
option rtapi_app no;
include <rtapi_math.h>;
include "carousel_decode.h";
license "GPL";
author "OpenEMC";
description """LinuxCNC's carousel. Each carousel N has pins carousel.N.* and a funct carousel.N.
Its module arguments are taken from entry N of each list; a missing or unusable entry
inherits carousel N-1's value (an unknown encoding is reported and ignored).

Encodings (sense-0 is the lowest bit): gray and binary read the pocket number from the
sense pins (gray 0 means the last pocket); bcd reads 4 pins per decimal digit; single has
one pin per pocket (the highest TRUE pin i means pocket i+1). index counts rising edges of
sense-1 while moving (sense-0 AND sense-1 is pocket 1 when homing); edge counts both edges
of sense-1; counts divides the encoder counts (from pocket 1) by scale, a pocket being
within width/2 counts of its position, and homes on the encoder index. index, edge and
counts home first (the carousel turns forward until the index is seen).

A move starts when enable is TRUE: bidirectional changers take the shorter way (a tie goes
in reverse when the target is below the current pocket). On arrival (after debounce
periods at the target) the motor reverses for rev-pulse seconds, or coasts for decel-time
seconds and aligns slowly at align-dc, or stops; ready then tells whether the right pocket
was reached (a failed final check is reported once). The state machine and its outputs
follow LinuxCNC, with the debounce counter and the failure message kept per instance.""";
;;
#define CAROUSEL_MAX 8
#define CAROUSEL_MAX_SENSE 32
#define ST_WAITING 0
#define ST_DIR_CHOOSE 1
#define ST_MOVE 2
#define ST_REV_TIME 3
#define ST_WAIT_STOP 5
#define ST_BACK_UP_INDEX 6
#define ST_BACK_OFF_INDEX 7
#define ST_FINAL_MOVE_BACK 8
#define ST_WAIT_ENABLE_FALSE 9
#define ST_HOME_START 10
#define ST_HOME_WAIT 11
#define ST_JOG 20

static int pockets[CAROUSEL_MAX] = {-1};
RTAPI_MP_ARRAY_INT(pockets, CAROUSEL_MAX, "number of pockets of each carousel");
static char *encoding[CAROUSEL_MAX];
RTAPI_MP_ARRAY_STRING(encoding, CAROUSEL_MAX, "position encoding of each carousel");
static int num_sense[CAROUSEL_MAX] = {-1};
RTAPI_MP_ARRAY_INT(num_sense, CAROUSEL_MAX, "number of sense pins of each carousel");
static int dir[CAROUSEL_MAX] = {-1};
RTAPI_MP_ARRAY_INT(dir, CAROUSEL_MAX, "1 unidirectional, 2 bidirectional");
static int parity[CAROUSEL_MAX] = {-1};
RTAPI_MP_ARRAY_INT(parity, CAROUSEL_MAX, "0 even, 1 odd parity of the position code");
static char *names = "";
RTAPI_MP_STRING(names, "instance names (one per carousel)");

/* One carousel's resolved module arguments. */
typedef struct {
    int n, letter, nsense, two_way, odd;
} carousel_cfg_t;

static carousel_cfg_t cfg[CAROUSEL_MAX];

/* The sense pins as a number, sense-0 the lowest bit; *xor gets their parity. */
static unsigned long sense_code(struct __comp_state *__comp_inst, int *xor)
{
    unsigned long v = 0;
    int i;
    *xor = 0;
    for (i = personality - 1; i >= 0; i--) {
        v = (v << 1) | (sense(i) ? 1 : 0);
        *xor ^= sense(i) ? 1 : 0;
    }
    return v;
}

/* Single encoding: the highest TRUE pin i gives i + 1, none 0; align is the current pocket's pin. */
static int decode_single(struct __comp_state *__comp_inst, int *align)
{
    int i, p = current_position;
    *align = p >= 1 && p <= personality && sense(p - 1);
    for (i = personality - 1; i >= 0; i--)
        if (sense(i)) return i + 1;
    return 0;
}

/* Index and edge encodings: count sense-1 edges in the motor's direction while homed. The edge memory
 * is the one homing keeps of the index (sense-0 AND sense-1), so the pocket sensor still TRUE when
 * homing ends is no new edge. */
static int decode_counted(struct __comp_state *__comp_inst, int *align)
{
    int p = current_position, s1 = sense(1) ? 1 : 0, edge;
    *align = enc == 'E' ? 1 : s1;
    if (!homed) return p;
    if (enc == 'I' && state != ST_MOVE && state != ST_JOG) return p;
    edge = enc == 'I' ? (s1 && !index_mem) : (s1 != index_mem);
    index_mem = s1;
    if (edge && motor_fwd) p++;
    if (edge && motor_rev) p--;
    return carousel_wrap(p, n_pockets);
}

/* Counts encoding: the pocket whose window holds the encoder position, while homed. */
static int decode_counts(struct __comp_state *__comp_inst, int *align)
{
    int p;
    *align = 0;
    if (!homed) return current_position;
    p = carousel_counts((long long)counts - base_counts, scale, width, n_pockets, align);
    return p ? p : current_position;
}

/* Decode the position, update current-position and parity-error while strobe; returns align. */
static int read_position(struct __comp_state *__comp_inst)
{
    int xor = 0, align = strobe ? 1 : 0, p;
    unsigned long code;
    if (enc == 'S') p = decode_single(__comp_inst, &align);
    else if (enc == 'I' || enc == 'E') p = decode_counted(__comp_inst, &align);
    else if (enc == 'C') p = decode_counts(__comp_inst, &align);
    else {
        code = sense_code(__comp_inst, &xor);
        if (enc == 'G') p = code ? (int)carousel_gray((unsigned)code) : n_pockets;
        else if (enc == 'D') p = (int)carousel_bcd(code, personality);
        else p = (int)code;
    }
    if (strobe) {
        current_position = p;
        parity_error = xor != (parity_arg ^ (parity_ ? 1 : 0));
    }
    return align;
}

/* Motor forward or reverse, or stopped at hold-dc (inactive). */
static void motor_forward(struct __comp_state *__comp_inst)
{
    motor_fwd = 1;
    motor_rev = 0;
    motor_vel = fwd_dc;
    motor_dir = 1;
}

static void motor_reverse(struct __comp_state *__comp_inst)
{
    motor_fwd = 0;
    motor_rev = 1;
    motor_vel = rev_dc;
    motor_dir = -1;
}

static void motor_stop(struct __comp_state *__comp_inst)
{
    motor_fwd = 0;
    motor_rev = 0;
    motor_vel = hold_dc;
    active = 0;
}

/* TRUE for the encodings that must home first. */
static int needs_homing(struct __comp_state *__comp_inst)
{
    return (enc == 'I' || enc == 'E' || enc == 'C') && !homed;
}

/* WAITING: start a jog, a homing or a move (the move continues in the same period). */
static int st_waiting(struct __comp_state *__comp_inst)
{
    motor_dir = 0;
    if (jog_fwd || (jog_rev && bidir)) {
        if (needs_homing(__comp_inst)) {
            state = ST_HOME_START;
            return 0;
        }
        target = current_position + (jog_fwd ? 1 : 0) - (jog_rev ? 1 : 0);
        counts_target += (double)scale * (target - current_position);
        target = carousel_wrap(target, n_pockets);
        if (jog_fwd) motor_forward(__comp_inst);
        else motor_reverse(__comp_inst);
        active = 1;
        state = ST_JOG;
        return 0;
    }
    motor_vel = hold_dc;
    if (!enable) return 0;
    active = 1;
    if (needs_homing(__comp_inst)) {
        state = ST_HOME_START;
        return 0;
    }
    ready = 0;
    fail_told = 0;
    state = ST_DIR_CHOOSE;
    return 1;
}

/* DIR_CHOOSE: pick the direction and the counts target; continues into MOVE. */
static int st_dir_choose(struct __comp_state *__comp_inst, int p)
{
    int cur = current_position, half = n_pockets / 2;
    if (!bidir) {
        counts_target += (double)(p - cur) * scale;
        if (counts_target < counts) counts_target += (double)scale * n_pockets;
        motor_forward(__comp_inst);
    } else if (cur < p && p - cur <= half) {
        counts_target += (double)(p - cur) * scale;
        motor_forward(__comp_inst);
    } else if (cur < p) {
        counts_target += (double)(p - cur - n_pockets) * scale;
        motor_reverse(__comp_inst);
    } else if (cur - p <= half) {
        counts_target += (double)(p - cur) * scale;
        motor_reverse(__comp_inst);
    } else {
        counts_target += (double)(p - cur + n_pockets) * scale;
        motor_forward(__comp_inst);
    }
    target = p;
    state = ST_MOVE;
    return 1;
}

/* TRUE once pos has been at target (or the move was dropped) for debounce periods. */
static int arrived(struct __comp_state *__comp_inst, int goal, int keep_going)
{
    if (current_position != goal && keep_going) {
        debounce_left = debounce;
        return 0;
    }
    if (debounce_left > 0) {
        debounce_left--;
        return 0;
    }
    return 1;
}

/* MOVE: on arrival pulse in reverse, coast, or stop. */
static void st_move(struct __comp_state *__comp_inst, int p)
{
    if (!arrived(__comp_inst, p, enable)) return;
    if (rev_pulse > 0) {
        motor_reverse(__comp_inst);
        motor_vel = rev_dc;
        timer = rev_pulse;
        state = ST_REV_TIME;
    } else if (decel_time > 0) {
        motor_vel = 0;
        timer = decel_time;
        state = ST_WAIT_STOP;
    } else {
        motor_stop(__comp_inst);
        ready = enable && current_position == p;
        state = ST_WAIT_ENABLE_FALSE;
    }
}

/* WAIT_STOP: after coasting, align slowly (backing up to the index when moving forward). */
static void st_wait_stop(struct __comp_state *__comp_inst, double t)
{
    timer -= t;
    if (timer > 0) return;
    if (align_dc == 0) {
        state = ST_FINAL_MOVE_BACK;
        return;
    }
    motor_vel = -align_dc;
    state = motor_dir == 1 ? ST_BACK_UP_INDEX : ST_BACK_OFF_INDEX;
}

/* HOME_START and HOME_WAIT: turn forward until the index is seen. */
static void st_home(struct __comp_state *__comp_inst)
{
    int ind = enc == 'C' ? sense(0) : (sense(0) && sense(1));
    if (state == ST_HOME_START) {
        homed = 0;
        homing = 1;
        motor_forward(__comp_inst);
        index_enable = 1;
        counts_target += (double)scale * n_pockets;
        index_mem = 1;
        state = ST_HOME_WAIT;
    }
    if (!index_enable || (ind && !index_mem)) {
        current_position = 1;
        homed = 1;
        homing = 0;
        active = 0;
        motor_fwd = 0;
        motor_rev = 0;
        motor_vel = 0;
        base_counts = counts - home_offset;
        counts_target = base_counts;
        timer = decel_time;
        state = align_dc == 0 ? ST_WAITING : ST_WAIT_STOP;
    }
    index_mem = ind ? 1 : 0;
}

/* JOG: stop at the target (aligned), then wait for the jog input to be released. */
static void st_jog(struct __comp_state *__comp_inst, int align)
{
    if (!arrived(__comp_inst, target, 1)) return;
    if (align_dc != 0 && !align) return;
    motor_stop(__comp_inst);
    if (jog_fwd || jog_rev) return;
    if (align_dc != 0) {
        motor_vel = -align_dc;
        timer = decel_time;
        state = ST_WAIT_STOP;
    } else {
        state = ST_WAITING;
    }
}

/* The waiting-for-enable and alignment states. */
static void st_finish(struct __comp_state *__comp_inst, int p, int align, double t)
{
    switch (state) {
    case ST_REV_TIME:
        timer -= t;
        if (timer > 0) return;
        motor_stop(__comp_inst);
        ready = enable;
        state = ST_WAIT_ENABLE_FALSE;
        return;
    case ST_BACK_UP_INDEX:
        if (align) state = ST_BACK_OFF_INDEX;
        return;
    case ST_BACK_OFF_INDEX:
        if (align) return;
        motor_vel = align_dc;
        state = ST_FINAL_MOVE_BACK;
        return;
    case ST_FINAL_MOVE_BACK:
        if (!align) return;
        motor_stop(__comp_inst);
        ready = enable && current_position == p;
        state = ST_WAIT_ENABLE_FALSE;
        return;
    default:
        if (!ready && !fail_told) {
            fail_told = 1;
            rtapi_print_msg(RTAPI_MSG_ERR, "The toolchanger has failed the final alignment check\n");
        }
        if (!enable) state = ST_WAITING;
    }
}

/* Run the state machine until a state says to wait for the next period. */
static void run_states(struct __comp_state *__comp_inst, int p, int align, double t)
{
    int again = 1;
    while (again) {
        again = 0;
        if (state == ST_WAITING) again = st_waiting(__comp_inst);
        else if (state == ST_DIR_CHOOSE) again = st_dir_choose(__comp_inst, p);
        else if (state == ST_MOVE) st_move(__comp_inst, p);
        else if (state == ST_WAIT_STOP) st_wait_stop(__comp_inst, t);
        else if (state == ST_HOME_START || state == ST_HOME_WAIT) st_home(__comp_inst);
        else if (state == ST_JOG) st_jog(__comp_inst, align);
        else st_finish(__comp_inst, p, align, t);
    }
}

FUNCTION(_)
{
    int align, p;
    if (!started) {
        started = 1;
        if (enc == 'G' || enc == 'B' || enc == 'D' || enc == 'S') homed = 1;
    }
    if (unhome && !unhome_mem) homed = 0;
    unhome_mem = unhome ? 1 : 0;
    align = read_position(__comp_inst);
    p = carousel_target(pocket_number, n_pockets);
    run_states(__comp_inst, p, align, fperiod);
}

static const struct { const char *word; int letter; } carousel_encodings[] = {
    {"gray", 'G'}, {"binary", 'B'}, {"bcd", 'D'}, {"single", 'S'}, {"index", 'I'}, {"edge", 'E'}, {"counts", 'C'},
};
#define CAROUSEL_N_ENC ((int)(sizeof(carousel_encodings) / sizeof(carousel_encodings[0])))

/* Encoding letter of a module argument starting with one of the encoding words, or 0. */
static int encoding_letter(const char *s)
{
    for (int k = 0; s && k < CAROUSEL_N_ENC; k++)
        if (strncmp(s, carousel_encodings[k].word, strlen(carousel_encodings[k].word)) == 0)
            return carousel_encodings[k].letter;
    return 0;
}

/* The word of an encoding letter. */
static const char *encoding_word(int letter)
{
    for (int k = 0; k < CAROUSEL_N_ENC; k++)
        if (carousel_encodings[k].letter == letter) return carousel_encodings[k].word;
    return "?";
}

/* Entry i of the module arguments over the values of entry i-1 (defaults for the first). */
static int resolve_cfg(int i, carousel_cfg_t *c)
{
    int letter = encoding_letter(encoding[i]);
    if (pockets[i] > 0) c->n = pockets[i];
    if (letter) c->letter = letter;
    else if (encoding[i] && encoding[i][0])
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: encoding '%s' of carousel %d is unknown; keeping %s\n",
                        encoding[i], i, encoding_word(c->letter));
    if (dir[i] > 1) c->two_way = 1;
    else if (dir[i] == 1) c->two_way = 0;
    if (parity[i] != -1) c->odd = parity[i] ? 1 : 0;
    if (num_sense[i] > 0) c->nsense = num_sense[i];
    if (c->letter == 'I') c->nsense = 2;
    if (c->letter == 'S' && c->nsense < c->n) c->nsense = c->n;
    if ((c->letter == 'E') && c->nsense < 2) c->nsense = 2;
    if (c->nsense > CAROUSEL_MAX_SENSE) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: carousel %d needs %d sense pins; at most %d are possible\n", i,
                        c->nsense, CAROUSEL_MAX_SENSE);
        return -EINVAL;
    }
    return 0;
}

/* Number of carousels: one per names= entry, else the pockets= entries before the first 0 (at least 1). */
static int carousel_count(void)
{
    int n = 0;
    if (names && names[0]) {
        for (const char *p = names; p; p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL) n++;
        return n;
    }
    while (n < CAROUSEL_MAX && pockets[n] != 0) n++;
    return n ? n : 1;
}

/* Name of carousel i into buf: its names= entry or carousel.<i>; -EINVAL for a bad entry. */
static int carousel_name(int i, char *buf, size_t len)
{
    const char *p = names;
    if (!names || !names[0]) {
        rtapi_snprintf(buf, len, "carousel.%d", i);
        return 0;
    }
    for (int k = 0; k < i; k++) p = strchr(p, ',') + 1;
    size_t n = strchr(p, ',') ? (size_t)(strchr(p, ',') - p) : strlen(p);
    if (n == 0 || n >= len) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: names entry %d is %s\n", i, n ? "too long" : "empty");
        return -EINVAL;
    }
    memcpy(buf, p, n);
    buf[n] = '\0';
    for (size_t k = 0; k < n; k++)
        if ((unsigned char)buf[k] <= ' ') {
            rtapi_print_msg(RTAPI_MSG_ERR, "carousel: names entry %d \"%s\" contains a blank\n", i, buf);
            return -EINVAL;
        }
    return 0;
}

/* Copy a carousel's resolved arguments into its instance. */
static void carousel_setup(struct __comp_state *__comp_inst, const carousel_cfg_t *c)
{
    n_pockets = c->n;
    enc = c->letter;
    bidir = c->two_way;
    parity_arg = c->odd;
}

/* Check every carousel's arguments, then create them. */
int rtapi_app_main(void)
{
    carousel_cfg_t c = {8, 'G', 4, 1, 0};
    char buf[HAL_NAME_LEN + 1];
    int i, r = 0, n = carousel_count();
    if (n > CAROUSEL_MAX) {
        rtapi_print_msg(RTAPI_MSG_ERR, "carousel: at most %d carousels\n", CAROUSEL_MAX);
        return -EINVAL;
    }
    for (i = 0; i < n; i++) {
        if (resolve_cfg(i, &c) || carousel_name(i, buf, sizeof(buf))) return -EINVAL;
        cfg[i] = c;
    }
    comp_id = hal_init("carousel");
    if (comp_id < 0) return comp_id;
    for (i = 0; i < n && r == 0; i++) {
        carousel_name(i, buf, sizeof(buf));
        r = export(buf, i, cfg[i].nsense);
        if (r == 0) carousel_setup(__comp_last_inst, &cfg[i]);
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
