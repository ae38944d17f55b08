/* sim_drive.c: the simulated CiA 402 drive: NMT slave, PDOs processed on SYNC, the drive state
   machine, a rate-limited motor following the target position, heartbeat and EMCY. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "sim_drive.h"

#define NS_PER_MS 1000000LL
#define DEFAULT_PERIOD_S 0.001
#define TORQUE_PER_COUNT 1.0         /* per mille of rated torque per count of following error */
#define TORQUE_LIMIT 3000.0
#define SYNC_TYPE_LAST 240
#define STATUS_REMOTE 0x0200u
#define STATUS_TARGET_REACHED 0x0400u
#define ERROR_REGISTER_GENERIC 0x01u

/* Statusword of each state (remote bit added separately). */
static const uint16_t status_of[] = {
    [CIA402_NOT_READY] = 0x0000, [CIA402_SWITCH_ON_DISABLED] = 0x0040, [CIA402_READY_TO_SWITCH_ON] = 0x0031,
    [CIA402_SWITCHED_ON] = 0x0033, [CIA402_OPERATION_ENABLED] = 0x0037, [CIA402_QUICK_STOP_ACTIVE] = 0x0017,
    [CIA402_FAULT_REACTION_ACTIVE] = 0x001F, [CIA402_FAULT] = 0x0018, [CIA402_UNKNOWN] = 0x0000,
};

/* Format and log a line through d->log. */
void sim_logf(sim_drive_t *d, const char *fmt, ...)
{
    char text[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    if (d->log)
        d->log(d->ctx, text);
}

/* Send a frame unless the cable is "cut". */
static void send(sim_drive_t *d, const co_frame_t *f)
{
    if (!d->silent)
        d->send(d->ctx, f);
}

/* Change the drive state, logging it. */
static void enter(sim_drive_t *d, cia402_state_t state)
{
    if (state == d->state)
        return;
    d->state = state;
    sim_logf(d, "node %d: state %s", d->node_id, cia402_state_name(state));
}

/* Copy position, velocity, torque and status into the dictionary. */
static void publish(sim_drive_t *d)
{
    int32_t target = (int32_t)sim_od_get(&d->od, CIA402_TARGET_POSITION, 0);
    int32_t actual = (int32_t)(uint32_t)(int64_t)llround(d->position);
    double error = (int32_t)((uint32_t)target - (uint32_t)actual);
    double torque = d->state == CIA402_OPERATION_ENABLED ? error * TORQUE_PER_COUNT : 0.0;
    uint16_t status = status_of[d->state] | STATUS_REMOTE;
    if (d->state == CIA402_OPERATION_ENABLED && fabs(error) < 1.0)
        status |= STATUS_TARGET_REACHED;
    torque = torque > TORQUE_LIMIT ? TORQUE_LIMIT : torque < -TORQUE_LIMIT ? -TORQUE_LIMIT : torque;
    sim_od_set(&d->od, CIA402_STATUSWORD, 0, status);
    sim_od_set(&d->od, CIA402_POSITION_ACTUAL, 0, (uint32_t)actual);
    sim_od_set(&d->od, CIA402_VELOCITY_ACTUAL, 0, (uint32_t)(int32_t)lround(d->velocity));
    sim_od_set(&d->od, CIA402_TORQUE_ACTUAL, 0, (uint16_t)(int16_t)lround(torque));
    sim_od_set(&d->od, CIA402_ERROR_CODE, 0, d->pending_emcy);
    sim_od_set(&d->od, CO_OBJ_ERROR_REGISTER, 0, d->pending_emcy ? ERROR_REGISTER_GENERIC : 0);
    sim_od_set(&d->od, CIA402_MODE_DISPLAY, 0, sim_od_get(&d->od, CIA402_MODE, 0));
}

/* Set up node node_id (call sim_drive_boot to power it on). */
void sim_drive_init(sim_drive_t *d, int node_id, double max_speed, sim_send_fn send_fn, sim_log_fn log, void *ctx)
{
    memset(d, 0, sizeof(*d));
    d->node_id = node_id;
    d->max_speed = max_speed;
    d->send = send_fn;
    d->log = log;
    d->ctx = ctx;
    d->nmt = CO_STATE_BOOTUP;
    sim_od_init(&d->od, node_id);
}

/* Power on or reset: dictionary to power-on values, boot-up message, pre-operational. */
void sim_drive_boot(sim_drive_t *d, long long now_ns)
{
    co_frame_t bootup = { .id = (uint16_t)(CO_HEARTBEAT + d->node_id), .len = 1, .data = { CO_STATE_BOOTUP } };
    sim_od_reset(&d->od, 0);
    d->state = CIA402_SWITCH_ON_DISABLED;
    d->previous_cw = 0;
    d->velocity = 0;
    d->pending_emcy = 0;
    memset(d->rpdo_fresh, 0, sizeof(d->rpdo_fresh));
    d->sync_count = 0;
    d->guard_toggle = 0;
    d->next_heartbeat_ns = 0;
    publish(d);
    send(d, &bootup);
    d->nmt = CO_STATE_PRE_OPERATIONAL;
    sim_logf(d, "node %d: boot-up", d->node_id);
    (void)now_ns;
}

/* Controlword commands (CiA 402). */
static int cw_shutdown(uint16_t cw) { return (cw & 0x87) == 0x06; }
static int cw_switch_on(uint16_t cw) { return (cw & 0x87) == 0x07; }
static int cw_enable(uint16_t cw) { return (cw & 0x8F) == 0x0F; }
static int cw_disable_operation(uint16_t cw) { return (cw & 0x8F) == 0x07; }
static int cw_disable_voltage(uint16_t cw) { return (cw & 0x82) == 0x00; }
static int cw_quick_stop(uint16_t cw) { return (cw & 0x86) == 0x02; }

/* One state machine step with the controlword of this cycle. */
static void step_state(sim_drive_t *d)
{
    uint16_t cw = (uint16_t)sim_od_get(&d->od, CIA402_CONTROLWORD, 0);
    int reset_edge = (cw & CIA402_CW_FAULT_RESET) && !(d->previous_cw & CIA402_CW_FAULT_RESET);
    co_frame_t clear = { .id = (uint16_t)(CO_EMCY + d->node_id), .len = 8 };
    d->previous_cw = cw;
    switch (d->state) {
    case CIA402_NOT_READY: enter(d, CIA402_SWITCH_ON_DISABLED); break;
    case CIA402_SWITCH_ON_DISABLED: if (cw_shutdown(cw)) enter(d, CIA402_READY_TO_SWITCH_ON); break;
    case CIA402_READY_TO_SWITCH_ON:
        if (cw_disable_voltage(cw) || cw_quick_stop(cw)) enter(d, CIA402_SWITCH_ON_DISABLED);
        else if (cw_switch_on(cw)) enter(d, CIA402_SWITCHED_ON);
        break;
    case CIA402_SWITCHED_ON:
        if (cw_disable_voltage(cw) || cw_quick_stop(cw)) enter(d, CIA402_SWITCH_ON_DISABLED);
        else if (cw_shutdown(cw)) enter(d, CIA402_READY_TO_SWITCH_ON);
        else if (cw_enable(cw)) enter(d, CIA402_OPERATION_ENABLED);
        break;
    case CIA402_OPERATION_ENABLED:
        if (cw_disable_voltage(cw)) enter(d, CIA402_SWITCH_ON_DISABLED);
        else if (cw_quick_stop(cw)) enter(d, CIA402_QUICK_STOP_ACTIVE);
        else if (cw_shutdown(cw)) enter(d, CIA402_READY_TO_SWITCH_ON);
        else if (cw_disable_operation(cw)) enter(d, CIA402_SWITCHED_ON);
        break;
    case CIA402_QUICK_STOP_ACTIVE: enter(d, CIA402_SWITCH_ON_DISABLED); break;
    case CIA402_FAULT_REACTION_ACTIVE: enter(d, CIA402_FAULT); break;
    case CIA402_FAULT:
        if (reset_edge) {
            d->pending_emcy = 0;
            send(d, &clear);
            enter(d, CIA402_SWITCH_ON_DISABLED);
        }
        break;
    default: break;
    }
}

/* The interpolation period from 0x60C2 (1 ms when unset). */
static double period_s(sim_drive_t *d)
{
    uint32_t digits = sim_od_get(&d->od, CIA402_INTERPOLATION_PERIOD, 1);
    int8_t exponent = (int8_t)sim_od_get(&d->od, CIA402_INTERPOLATION_PERIOD, 2);
    return digits ? digits * pow(10.0, exponent) : DEFAULT_PERIOD_S;
}

/* Move toward the target position at up to max_speed (cyclic synchronous position mode only). */
static void step_motor(sim_drive_t *d)
{
    double dt = period_s(d), step;
    int32_t target = (int32_t)sim_od_get(&d->od, CIA402_TARGET_POSITION, 0);
    long long whole = llround(d->position);
    int32_t actual = (int32_t)(uint32_t)(uint64_t)whole;
    double error = (int32_t)((uint32_t)target - (uint32_t)actual) - (d->position - (double)whole);
    if (d->state != CIA402_OPERATION_ENABLED || (int8_t)sim_od_get(&d->od, CIA402_MODE, 0) != CIA402_MODE_CSP) {
        d->velocity = 0;
        return;
    }
    step = error;
    if (fabs(step) > d->max_speed * dt)
        step = step > 0 ? d->max_speed * dt : -d->max_speed * dt;
    d->position += step;
    d->velocity = step / dt;
}

/* Send TPDO p (index 0 or 1) with its mapped objects. */
static void send_tpdo(sim_drive_t *d, int p, uint32_t cob_id)
{
    co_frame_t f = { .id = (uint16_t)(cob_id & CO_ID_MASK) };
    f.len = (uint8_t)sim_od_pack(&d->od, (uint16_t)(CO_OBJ_TPDO_MAP + p), f.data);
    send(d, &f);
}

/* A SYNC: take the RPDOs, run the drive one period, send the synchronous TPDOs. */
static void on_sync(sim_drive_t *d)
{
    d->sync_count++;
    for (int p = 0; p < SIM_PDO_COUNT; p++)
        if (d->rpdo_fresh[p]) {
            d->rpdo_fresh[p] = 0;
            if (sim_od_unpack(&d->od, (uint16_t)(CO_OBJ_RPDO_MAP + p), d->rpdo_data[p], d->rpdo_len[p]) != 0)
                sim_logf(d, "node %d: RPDO%d shorter than its mapping, ignored", d->node_id, p + 1);
        }
    step_state(d);
    step_motor(d);
    publish(d);
    for (int p = 0; p < SIM_PDO_COUNT; p++) {
        uint32_t cob_id = sim_od_get(&d->od, (uint16_t)(CO_OBJ_TPDO_COMM + p), 1);
        uint32_t type = sim_od_get(&d->od, (uint16_t)(CO_OBJ_TPDO_COMM + p), 2);
        if (!(cob_id & CO_PDO_INVALID) && type <= SYNC_TYPE_LAST && (type == 0 || d->sync_count % type == 0))
            send_tpdo(d, p, cob_id);
    }
}

/* An RPDO: synchronous ones wait for the next SYNC, the others apply at once. */
static void on_rpdo(sim_drive_t *d, int p, const co_frame_t *f)
{
    uint32_t type = sim_od_get(&d->od, (uint16_t)(CO_OBJ_RPDO_COMM + p), 2);
    if (type <= SYNC_TYPE_LAST) {
        memcpy(d->rpdo_data[p], f->data, 8);
        d->rpdo_len[p] = f->len;
        d->rpdo_fresh[p] = 1;
    } else if (sim_od_unpack(&d->od, (uint16_t)(CO_OBJ_RPDO_MAP + p), f->data, f->len) != 0) {
        sim_logf(d, "node %d: RPDO%d shorter than its mapping, ignored", d->node_id, p + 1);
    }
}

/* An NMT command for this node. */
static void on_nmt(sim_drive_t *d, uint8_t command, long long now_ns)
{
    static const struct { uint8_t command, state; const char *name; } moves[] = {
        { CO_NMT_START, CO_STATE_OPERATIONAL, "operational" },
        { CO_NMT_STOP, CO_STATE_STOPPED, "stopped" },
        { CO_NMT_PRE_OPERATIONAL, CO_STATE_PRE_OPERATIONAL, "pre-operational" },
    };
    if (command == CO_NMT_RESET_NODE || command == CO_NMT_RESET_COMMUNICATION) {
        if (command == CO_NMT_RESET_COMMUNICATION)
            sim_od_reset(&d->od, 1);
        sim_drive_boot(d, now_ns);
        return;
    }
    for (unsigned i = 0; i < sizeof(moves) / sizeof(moves[0]); i++)
        if (moves[i].command == command) {
            if (d->nmt == CO_STATE_OPERATIONAL && moves[i].state != CO_STATE_OPERATIONAL &&
                d->state == CIA402_OPERATION_ENABLED)
                enter(d, CIA402_SWITCHED_ON);
            if (d->nmt != moves[i].state)
                sim_logf(d, "node %d: nmt %s", d->node_id, moves[i].name);
            d->nmt = moves[i].state;
        }
}

/* Take one frame from the bus. */
void sim_drive_receive(sim_drive_t *d, const co_frame_t *f, long long now_ns)
{
    uint32_t sync_id = sim_od_get(&d->od, CO_OBJ_SYNC_COB_ID, 0) & CO_ID_MASK;
    if (d->silent || d->nmt == CO_STATE_BOOTUP)
        return;
    if (f->id == CO_NMT && f->len == 2 && !f->rtr) {
        if (f->data[1] == 0 || f->data[1] == d->node_id)
            on_nmt(d, f->data[0], now_ns);
    } else if (f->id == sync_id && !f->rtr) {
        if (d->nmt == CO_STATE_OPERATIONAL)
            on_sync(d);
    } else if (f->id == CO_SDO_RX + d->node_id && !f->rtr) {
        sim_sdo_request(d, f);
    } else if (f->id == CO_HEARTBEAT + d->node_id && f->rtr) {
        co_frame_t guard = { .id = f->id, .len = 1, .data = { (uint8_t)(d->nmt | d->guard_toggle) } };
        d->guard_toggle ^= 0x80;
        send(d, &guard);
    } else if (d->nmt == CO_STATE_OPERATIONAL && !f->rtr) {
        for (int p = 0; p < SIM_PDO_COUNT; p++) {
            uint32_t cob_id = sim_od_get(&d->od, (uint16_t)(CO_OBJ_RPDO_COMM + p), 1);
            if (!(cob_id & CO_PDO_INVALID) && (cob_id & CO_ID_MASK) == f->id)
                on_rpdo(d, p, f);
        }
    }
}

/* Time passes: the heartbeat every 0x1017 milliseconds. */
void sim_drive_tick(sim_drive_t *d, long long now_ns)
{
    long long period = sim_od_get(&d->od, CO_OBJ_HEARTBEAT_TIME, 0) * NS_PER_MS;
    co_frame_t beat = { .id = (uint16_t)(CO_HEARTBEAT + d->node_id), .len = 1, .data = { d->nmt } };
    if (period == 0 || d->nmt == CO_STATE_BOOTUP) {
        d->next_heartbeat_ns = 0;
        return;
    }
    if (d->next_heartbeat_ns == 0)
        d->next_heartbeat_ns = now_ns + period;
    if (now_ns < d->next_heartbeat_ns)
        return;
    send(d, &beat);
    d->next_heartbeat_ns = now_ns - d->next_heartbeat_ns > period ? now_ns + period : d->next_heartbeat_ns + period;
}

/* Send an EMCY; a non-zero code also puts the drive into Fault until a fault reset. */
void sim_drive_emcy(sim_drive_t *d, uint16_t code)
{
    co_frame_t f = { .id = (uint16_t)(CO_EMCY + d->node_id), .len = 8 };
    co_put16(f.data, code);
    f.data[2] = code ? ERROR_REGISTER_GENERIC : 0;
    if (code) {
        d->pending_emcy = code;
        enter(d, d->nmt == CO_STATE_OPERATIONAL ? CIA402_FAULT_REACTION_ACTIVE : CIA402_FAULT);
        publish(d);
    }
    sim_logf(d, "node %d: emcy 0x%04X", d->node_id, code);
    send(d, &f);
}

/* Change the NMT state on the drive's own account (as a local fault would) and announce it
   with a heartbeat at once. */
void sim_drive_set_nmt(sim_drive_t *d, uint8_t state)
{
    co_frame_t beat = { .id = (uint16_t)(CO_HEARTBEAT + d->node_id), .len = 1, .data = { state } };
    d->nmt = state;
    sim_logf(d, "node %d: nmt state 0x%02X", d->node_id, state);
    send(d, &beat);
}

/* Send one malformed frame of the given kind (SDO: the next answer is cut short). */
void sim_drive_send_bad(sim_drive_t *d, sim_bad_kind_t kind)
{
    co_frame_t f = { .len = 2 };
    switch (kind) {
    case SIM_BAD_TPDO1: f.id = (uint16_t)(CO_TPDO1 + d->node_id); f.len = 4; break;
    case SIM_BAD_HEARTBEAT: f.id = (uint16_t)(CO_HEARTBEAT + d->node_id); f.data[0] = d->nmt; break;
    case SIM_BAD_EMCY: f.id = (uint16_t)(CO_EMCY + d->node_id); f.len = 1; f.data[0] = 0x10; break;
    case SIM_BAD_SDO: d->bad_sdo_next = 1; return;
    }
    send(d, &f);
}
