/* cia402_node.c: one CiA 402 drive seen from the master: frames received, supervision, faults. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include "cia402_node.h"

#define NS_PER_MS 1000000LL
#define PDO_BYTES 6                 /* TPDO1, TPDO2 and RPDO1 all carry 16 + 32 bits */
#define EMCY_BYTES 8
#define RESET_GRACE_TPDOS 3         /* statuswords ignored after a fault reset while the drive clears */

/* Malformed frame kinds, each reported once until the next reset. */
enum { BAD_HEARTBEAT = 1, BAD_TPDO1 = 2, BAD_TPDO2 = 4, BAD_EMCY = 8, BAD_SDO = 16 };

/* Format a message into n->msg and hand it to the report sink. */
static void say(cia402_node_t *n, int is_error, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(n->msg, sizeof(n->msg), fmt, ap);
    va_end(ap);
    n->report(n->report_ctx, is_error, n->msg);
}

/* Latch fault f (the first one is reported, naming the node); link faults also take the link down. */
static void latch(cia402_node_t *n, cia402_fault_t f, int link_down, long long now_ns, const char *fmt, ...)
{
    char why[CIA402_MSG_LEN / 2];
    va_list ap;
    if (link_down && n->link != CIA402_LINK_DOWN) {
        n->link = CIA402_LINK_DOWN;
        n->link_since_ns = now_ns;
        n->sdo_pending = 0;
    }
    if (n->fault != CIA402_FAULT_NONE)
        return;
    n->fault = f;
    va_start(ap, fmt);
    vsnprintf(why, sizeof(why), fmt, ap);
    va_end(ap);
    say(n, 1, "%s: %s; outputs disabled", n->label, why);
}

/* Count a malformed frame and report its kind once. */
static void bad_frame(cia402_node_t *n, unsigned kind, const char *name, int len, int expected)
{
    n->bad_frames++;
    if (n->bad_reported & kind)
        return;
    n->bad_reported |= kind;
    say(n, 1, "%s: malformed %s (length %d, expected %d) ignored", n->label, name, len, expected);
}

/* Start (or restart) the set-up sequence. */
static void restart_setup(cia402_node_t *n, long long now_ns)
{
    n->link = CIA402_LINK_CONFIGURE;
    n->step = 0;
    n->sdo_pending = 0;
    n->sdo_answered = 0;
    n->absent = 0;
    n->link_since_ns = now_ns;
}

/* Prepare a node for drive cfg. */
void cia402_node_init(cia402_node_t *n, const cia402_drive_cfg_t *cfg, const char *config_path,
                      cia402_report_fn report, void *ctx)
{
    *n = (cia402_node_t){ .cfg = cfg, .config_path = config_path, .report = report, .report_ctx = ctx };
    snprintf(n->label, sizeof(n->label), "cia402: drive %d (node %d on %s)", cfg->number, cfg->node_id,
             cfg->interface);
    n->step_count = cia402_setup_build(cfg, n->steps);
    restart_setup(n, 0);
}

/* The link reached NMT operational. */
static void become_running(cia402_node_t *n, long long now_ns)
{
    n->link = CIA402_LINK_RUNNING;
    n->was_running = 1;
    n->link_since_ns = n->last_tpdo1_ns = n->last_heartbeat_ns = now_ns;
    if (n->enable_prev)
        n->enable_since_ns = now_ns;
    say(n, 0, "%s: configured and operational", n->label);
}

/* The node sent its boot-up message. */
static void on_bootup(cia402_node_t *n, long long now_ns)
{
    switch (n->link) {
    case CIA402_LINK_CONFIGURE:
        restart_setup(n, now_ns);
        break;
    case CIA402_LINK_STARTING:
    case CIA402_LINK_RUNNING:
        latch(n, CIA402_FAULT_REBOOTED, 1, now_ns, "node rebooted (boot-up message)");
        break;
    case CIA402_LINK_DOWN:
        if (n->absent) {
            say(n, 0, "%s: node booted; configuring", n->label);
            n->fault = CIA402_FAULT_NONE;
            restart_setup(n, now_ns);
        }
        break;
    }
}

/* The name of an NMT state byte. */
static const char *nmt_name(uint8_t state)
{
    switch (state) {
    case CO_STATE_STOPPED: return "stopped";
    case CO_STATE_OPERATIONAL: return "operational";
    case CO_STATE_PRE_OPERATIONAL: return "pre-operational";
    default: return "an unknown state";
    }
}

/* Heartbeat or boot-up message. */
static void on_heartbeat(cia402_node_t *n, const co_frame_t *f, long long now_ns)
{
    uint8_t state;
    if (f->len != 1) {
        bad_frame(n, BAD_HEARTBEAT, "heartbeat", f->len, 1);
        return;
    }
    state = f->data[0] & 0x7F;
    n->nmt_state = state;
    if (state == CO_STATE_BOOTUP) {
        on_bootup(n, now_ns);
        return;
    }
    n->last_heartbeat_ns = now_ns;
    if (n->link == CIA402_LINK_STARTING && state == CO_STATE_OPERATIONAL)
        become_running(n, now_ns);
    else if (n->link == CIA402_LINK_RUNNING && state != CO_STATE_OPERATIONAL)
        latch(n, CIA402_FAULT_NOT_OPERATIONAL, 1, now_ns, "node left NMT operational (heartbeat reports %s)",
              nmt_name(state));
}

/* TPDO1: statusword and position actual value. */
static void on_tpdo1(cia402_node_t *n, const co_frame_t *f, long long now_ns)
{
    int32_t raw;
    if (n->link == CIA402_LINK_CONFIGURE || (n->link == CIA402_LINK_DOWN && !n->was_running))
        return;
    if (f->len != PDO_BYTES) {
        bad_frame(n, BAD_TPDO1, "TPDO1", f->len, PDO_BYTES);
        return;
    }
    raw = (int32_t)co_get32(&f->data[2]);
    if (!n->have_status)
        n->position_counts = raw;
    else
        n->position_counts += (int32_t)((uint32_t)raw - (uint32_t)n->position_raw);
    n->position_raw = raw;
    n->statusword = co_get16(f->data);
    n->have_status = 1;
    n->last_tpdo1_ns = now_ns;
    if (n->reset_grace > 0)
        n->reset_grace--;
    if (n->link == CIA402_LINK_STARTING)
        become_running(n, now_ns);
}

/* TPDO2: velocity and torque actual values. */
static void on_tpdo2(cia402_node_t *n, const co_frame_t *f)
{
    if (!n->cfg->velocity_feedback || n->link == CIA402_LINK_CONFIGURE)
        return;
    if (f->len != PDO_BYTES) {
        bad_frame(n, BAD_TPDO2, "TPDO2", f->len, PDO_BYTES);
        return;
    }
    n->velocity_raw = (int32_t)co_get32(f->data);
    n->torque_raw = (int16_t)co_get16(&f->data[4]);
    n->have_tpdo2 = 1;
}

/* Emergency message: any error code but 0 (error reset) latches a fault. */
static void on_emcy(cia402_node_t *n, const co_frame_t *f, long long now_ns)
{
    uint16_t code;
    if (f->len != EMCY_BYTES)
        bad_frame(n, BAD_EMCY, "EMCY", f->len, EMCY_BYTES);
    if (f->len < 2) {
        latch(n, CIA402_FAULT_EMCY, 0, now_ns, "malformed EMCY treated as an emergency");
        return;
    }
    code = co_get16(f->data);
    if (code == 0) {
        say(n, 0, "%s: EMCY error reset", n->label);
        return;
    }
    n->error_code = code;
    latch(n, CIA402_FAULT_EMCY, 0, now_ns, "EMCY error code 0x%04X (error register 0x%02X)", code,
          f->len > 2 ? f->data[2] : 0);
}

/* A set-up step went wrong: report it with the configuration line that asked for it. */
static void setup_failed(cia402_node_t *n, const cia402_step_t *s, long long now_ns, const char *why)
{
    latch(n, CIA402_FAULT_SETUP, 1, now_ns, "%s:%d: %s (SDO %04X:%02X = %u) %s", n->config_path, s->line,
          s->what, s->write.index, s->write.sub, s->write.value, why);
}

/* Answer from the node's SDO server. */
static void on_sdo(cia402_node_t *n, const co_frame_t *f, long long now_ns)
{
    const cia402_step_t *s = &n->steps[n->step];
    char why[CIA402_MSG_LEN / 4];
    uint32_t abort_code = 0;
    if (n->link != CIA402_LINK_CONFIGURE || !n->sdo_pending)
        return;
    switch (co_sdo_download_reply(f, &s->write, &abort_code)) {
    case CO_SDO_REPLY_DONE:
        n->sdo_pending = 0;
        n->sdo_answered = 1;
        n->step++;
        break;
    case CO_SDO_REPLY_ABORT:
        n->sdo_answered = 1;
        snprintf(why, sizeof(why), "refused: abort 0x%08X, %s", abort_code, co_abort_text(abort_code));
        setup_failed(n, s, now_ns, why);
        break;
    case CO_SDO_REPLY_MALFORMED:
        bad_frame(n, BAD_SDO, "SDO answer", f->len, 8);
        setup_failed(n, s, now_ns, "answered with a malformed SDO frame");
        break;
    case CO_SDO_REPLY_UNRELATED:
        break;
    }
}

/* Take one frame addressed from this node. */
void cia402_node_receive(cia402_node_t *n, const co_frame_t *f, long long now_ns)
{
    if (f->rtr)
        return;
    switch (f->id & CO_FUNC_MASK) {
    case CO_HEARTBEAT: on_heartbeat(n, f, now_ns); break;
    case CO_TPDO1: on_tpdo1(n, f, now_ns); break;
    case CO_TPDO2: on_tpdo2(n, f); break;
    case CO_EMCY: on_emcy(n, f, now_ns); break;
    case CO_SDO_TX: on_sdo(n, f, now_ns); break;
    default: break;
    }
}

/* The drive state from the last statusword. */
cia402_state_t cia402_node_state(const cia402_node_t *n)
{
    return n->have_status ? cia402_decode(n->statusword) : CIA402_UNKNOWN;
}

/* Set-up supervision: every SDO must be answered in SDO_TIMEOUT_MS. */
static void check_configure(cia402_node_t *n, long long now_ns)
{
    const cia402_drive_cfg_t *c = n->cfg;
    const cia402_step_t *s = &n->steps[n->step];
    char why[CIA402_MSG_LEN / 4];
    if (!n->sdo_pending || now_ns - n->sdo_sent_ns <= c->sdo_timeout_ms * NS_PER_MS)
        return;
    if (n->sdo_answered) {
        snprintf(why, sizeof(why), "got no answer within %d ms", c->sdo_timeout_ms);
        setup_failed(n, s, now_ns, why);
        return;
    }
    latch(n, CIA402_FAULT_NO_ANSWER, 1, now_ns, "no answer to SDO requests within %d ms (drive off, wrong "
          "NODE_ID at %s:%d or wrong bitrate?)", c->sdo_timeout_ms, n->config_path,
          c->node_line ? c->node_line : c->section_line);
    n->absent = 1;
}

/* Running supervision: heartbeat, feedback, drive state and the enable time. */
static void check_running(cia402_node_t *n, long long now_ns)
{
    const cia402_drive_cfg_t *c = n->cfg;
    cia402_state_t st = cia402_node_state(n);
    if (now_ns - n->last_heartbeat_ns > c->heartbeat_timeout_ms * NS_PER_MS) {
        latch(n, CIA402_FAULT_HEARTBEAT, 1, now_ns, "heartbeat lost (none for %lld ms)",
              (now_ns - n->last_heartbeat_ns) / NS_PER_MS);
        return;
    }
    if (now_ns - n->last_tpdo1_ns > c->pdo_timeout_ms * NS_PER_MS) {
        latch(n, CIA402_FAULT_FEEDBACK, 1, now_ns, "no position feedback (TPDO1) for %lld ms",
              (now_ns - n->last_tpdo1_ns) / NS_PER_MS);
        return;
    }
    if (n->reset_grace > 0)
        return;                      /* a fault reset is still being taken up by the drive */
    if (st == CIA402_FAULT || st == CIA402_FAULT_REACTION_ACTIVE || st == CIA402_QUICK_STOP_ACTIVE)
        latch(n, CIA402_FAULT_DRIVE, 0, now_ns, "drive reports %s (statusword 0x%04X)", cia402_state_name(st),
              n->statusword);
    else if (n->enable_prev && n->enable_since_ns && st != CIA402_OPERATION_ENABLED &&
             now_ns - n->enable_since_ns > c->enable_timeout_ms * NS_PER_MS)
        latch(n, CIA402_FAULT_ENABLE_TIMEOUT, 0, now_ns, "drive did not reach Operation enabled within %d ms "
              "(it is in %s)", c->enable_timeout_ms, cia402_state_name(st));
}

/* Supervise timeouts and the drive state after the frames of a cycle were received. */
void cia402_node_check(cia402_node_t *n, long long now_ns)
{
    switch (n->link) {
    case CIA402_LINK_CONFIGURE:
        check_configure(n, now_ns);
        break;
    case CIA402_LINK_STARTING:
        if (now_ns - n->link_since_ns > n->cfg->heartbeat_timeout_ms * NS_PER_MS)
            latch(n, CIA402_FAULT_NOT_OPERATIONAL, 1, now_ns, "did not become NMT operational within %d ms "
                  "of the start command", n->cfg->heartbeat_timeout_ms);
        break;
    case CIA402_LINK_RUNNING:
        check_running(n, now_ns);
        break;
    case CIA402_LINK_DOWN:
        break;
    }
}

/* TRUE while the drive follows the position command. */
int cia402_node_enabled(const cia402_node_t *n)
{
    return n->link == CIA402_LINK_RUNNING && n->fault == CIA402_FAULT_NONE && n->enable_prev &&
           cia402_node_state(n) == CIA402_OPERATION_ENABLED;
}

/* A rising edge of fault-reset or enable: clear latched faults; a link fault restarts the set-up. */
static void reset_faults(cia402_node_t *n, long long now_ns)
{
    cia402_state_t st = cia402_node_state(n);
    if (n->fault == CIA402_FAULT_NONE && n->link != CIA402_LINK_DOWN)
        return;
    n->fault = CIA402_FAULT_NONE;
    n->error_code = 0;
    n->bad_reported = 0;
    n->reset_grace = RESET_GRACE_TPDOS;
    n->enable_since_ns = now_ns;
    if (n->link == CIA402_LINK_DOWN) {
        say(n, 0, "%s: reset: configuring again", n->label);
        restart_setup(n, now_ns);
        return;
    }
    say(n, 0, "%s: reset", n->label);
    if (st == CIA402_FAULT || st == CIA402_FAULT_REACTION_ACTIVE)
        n->send_fault_reset = 1;
}

/* An NMT command to this node. */
static int nmt_frame(cia402_node_t *n, uint8_t command, co_frame_t *out)
{
    *out = (co_frame_t){ .id = CO_NMT, .len = 2, .data = { command, (uint8_t)n->cfg->node_id } };
    return 1;
}

/* The next set-up frame, when no SDO answer is awaited. */
static int setup_transmit(cia402_node_t *n, long long now_ns, long period_ns, co_frame_t *out)
{
    cia402_step_t *s = &n->steps[n->step];
    if (n->sdo_pending || n->step >= n->step_count)
        return 0;
    switch (s->kind) {
    case CIA402_STEP_PRE_OPERATIONAL:
        n->step++;
        return nmt_frame(n, CO_NMT_PRE_OPERATIONAL, out);
    case CIA402_STEP_SDO:
        s->write.value = cia402_setup_value(s, period_ns);
        co_sdo_download_frame((uint8_t)n->cfg->node_id, &s->write, out);
        n->sdo_pending = 1;
        n->sdo_sent_ns = now_ns;
        return 1;
    case CIA402_STEP_START:
        n->link = CIA402_LINK_STARTING;
        n->link_since_ns = n->last_heartbeat_ns = now_ns;
        return nmt_frame(n, CO_NMT_START, out);
    }
    return 0;
}

/* The target position for the command, or the actual position while not following. */
static int32_t target_for(cia402_node_t *n, const cia402_command_t *cmd, long long now_ns)
{
    const double max_counts = 9.0e15;   /* well inside the exact range of a double */
    double counts = cmd->position_cmd * n->cfg->position_scale;
    if (!cia402_node_enabled(n))
        return n->position_raw;
    if (!isfinite(counts) || fabs(counts) > max_counts) {
        latch(n, CIA402_FAULT_COMMAND, 0, now_ns, "position command is not a number within range");
        return n->position_raw;
    }
    return (int32_t)(uint32_t)(uint64_t)llround(counts);
}

/* RPDO1: the controlword for the wanted state and the target position. */
static int rpdo_transmit(cia402_node_t *n, const cia402_command_t *cmd, long long now_ns, co_frame_t *out)
{
    uint16_t cw;
    int32_t target = target_for(n, cmd, now_ns);
    if (n->send_fault_reset) {
        cw = CIA402_CW_FAULT_RESET;
        n->send_fault_reset = 0;
    } else if (n->fault != CIA402_FAULT_NONE || n->link != CIA402_LINK_RUNNING) {
        cw = CIA402_CW_DISABLE_OPERATION;
    } else if (cmd->enable) {
        cw = cia402_enable_step(cia402_node_state(n));
    } else {
        cw = CIA402_CW_SHUTDOWN;
    }
    n->controlword = cw;
    n->target = target;
    *out = (co_frame_t){ .id = (uint16_t)(CO_RPDO1 + n->cfg->node_id), .len = PDO_BYTES };
    co_put16(out->data, cw);
    co_put32(&out->data[2], (uint32_t)target);
    return 1;
}

/* Apply this cycle's command; writes up to CIA402_FRAMES_PER_CYCLE frames to out, returns the count. */
int cia402_node_transmit(cia402_node_t *n, const cia402_command_t *cmd, long long now_ns, long period_ns,
                         co_frame_t *out)
{
    int enable_edge = cmd->enable && !n->enable_prev;
    if ((cmd->fault_reset && !n->reset_prev) || enable_edge)
        reset_faults(n, now_ns);
    if (enable_edge || (cmd->enable && !n->enable_since_ns))
        n->enable_since_ns = now_ns;
    if (!cmd->enable)
        n->enable_since_ns = 0;
    n->enable_prev = cmd->enable;
    n->reset_prev = cmd->fault_reset;
    switch (n->link) {
    case CIA402_LINK_CONFIGURE:
        return setup_transmit(n, now_ns, period_ns, out);
    case CIA402_LINK_RUNNING:
        return rpdo_transmit(n, cmd, now_ns, out);
    case CIA402_LINK_DOWN:
        return n->was_running ? rpdo_transmit(n, cmd, now_ns, out) : 0;
    default:
        return 0;
    }
}

/* The frames that leave the drive safe when the driver unloads. */
int cia402_node_goodbye(cia402_node_t *n, co_frame_t *rpdo, co_frame_t *nmt)
{
    nmt_frame(n, CO_NMT_PRE_OPERATIONAL, nmt);
    if (!n->was_running || n->link == CIA402_LINK_CONFIGURE || n->link == CIA402_LINK_STARTING)
        return 0;
    n->controlword = CIA402_CW_SHUTDOWN;
    n->target = n->position_raw;
    *rpdo = (co_frame_t){ .id = (uint16_t)(CO_RPDO1 + n->cfg->node_id), .len = PDO_BYTES };
    co_put16(rpdo->data, n->controlword);
    co_put32(&rpdo->data[2], (uint32_t)n->target);
    return 1;
}
