/* cia402.c: HAL driver for CANopen CiA 402 servo drives on SocketCAN, in cyclic synchronous
   position mode: pins per drive, the read and write functs, SYNC every write. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "can_bus.h"
#include "cia402_config.h"
#include "cia402_node.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("CANopen CiA 402 drives (cyclic synchronous position) on SocketCAN: config=FILE");

static char *config;
RTAPI_MP_STRING(config, "the drive configuration file ([CIA402] and [CIA402_DRIVE_n] sections)");

#define RX_ROUNDS_MAX 16            /* at most 16 x 32 frames are taken per bus and cycle */
#define IDS_PER_NODE 5
#define NO_NODE (-1)
#define NS_PER_S 1e9
#define TORQUE_PERMILLE_PER_PERCENT 10.0

/* HAL pins of one drive (HAL memory). */
typedef struct {
    hal_bit_t *enable, *fault_reset;
    hal_float_t *position_cmd;
    hal_float_t *position_fb, *velocity_fb, *torque_fb;
    hal_bit_t *enabled, *fault, *ready;
    hal_u32_t *fault_code, *error_code, *statusword, *controlword, *nmt_state, *bad_frames;
    hal_s32_t *state;
} drive_pins_t;

/* One interface and which drive each node id belongs to. */
typedef struct {
    char name[CAN_BUS_NAME_LEN];
    can_bus_t io;
    int node_of[CO_MAX_NODE + 1];
    hal_u32_t *tx_dropped;
    int error_reported;
} bus_t;

/* Everything the module owns (user-space memory, allocated at load). */
typedef struct {
    cia402_cfg_t cfg;
    cia402_node_t nodes[CIA402_MAX_DRIVES];
    int bus_of[CIA402_MAX_DRIVES];
    int64_t previous_counts[CIA402_MAX_DRIVES];
    bus_t buses[CIA402_MAX_DRIVES];
    int bus_count;
    drive_pins_t *pins;
} cia402_t;

static int comp_id = -1;
static cia402_t *self;

/* Message sink of the configuration reader. */
static void config_report(void *ctx, const char *text)
{
    (void)ctx;
    rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", text);
}

/* Message sink of the drives (also called in the realtime thread: the message is queued). */
static void node_report(void *ctx, int is_error, const char *text)
{
    (void)ctx;
    rtapi_print_msg(is_error ? RTAPI_MSG_ERR : RTAPI_MSG_INFO, "%s\n", text);
}

/* Report a bus error once (queued when called in the realtime thread). */
static void bus_failed(bus_t *b, const char *what, int error)
{
    if (b->error_reported)
        return;
    b->error_reported = 1;
    rtapi_print_msg(RTAPI_MSG_ERR, "cia402: %s: %s failed: %s\n", b->io.name, what, strerror(-error));
}

/* Hand every pending frame of bus b to its drive. */
static void receive_bus(bus_t *b, long long now_ns)
{
    co_frame_t frames[CAN_BUS_BATCH];
    int got = CAN_BUS_BATCH, valid;
    for (int round = 0; round < RX_ROUNDS_MAX && got == CAN_BUS_BATCH; round++) {
        got = can_bus_receive(&b->io, frames, CAN_BUS_BATCH, &valid);
        if (got < 0) {
            bus_failed(b, "receive", got);
            return;
        }
        for (int i = 0; i < valid; i++) {
            int d = (frames[i].id & CO_FUNC_MASK) ? b->node_of[frames[i].id & CO_NODE_MASK] : NO_NODE;
            if (d != NO_NODE)
                cia402_node_receive(&self->nodes[d], &frames[i], now_ns);
        }
    }
}

/* Copy the state of drive d to its output pins. */
static void update_pins(int d, long period_ns)
{
    const cia402_node_t *n = &self->nodes[d];
    drive_pins_t *p = &self->pins[d];
    double scale = n->cfg->position_scale;
    *p->position_fb = (double)n->position_counts / scale;
    if (n->cfg->velocity_feedback)
        *p->velocity_fb = n->velocity_raw / scale;
    else if (period_ns > 0)
        *p->velocity_fb = (double)(n->position_counts - self->previous_counts[d]) / scale / (period_ns / NS_PER_S);
    self->previous_counts[d] = n->position_counts;
    *p->torque_fb = n->torque_raw / TORQUE_PERMILLE_PER_PERCENT;
    *p->enabled = cia402_node_enabled(n);
    *p->fault = n->fault != CIA402_FAULT_NONE;
    *p->ready = n->link == CIA402_LINK_RUNNING && n->fault == CIA402_FAULT_NONE;
    *p->fault_code = n->fault;
    *p->error_code = n->error_code;
    *p->statusword = n->statusword;
    *p->controlword = n->controlword;
    *p->nmt_state = n->nmt_state;
    *p->bad_frames = n->bad_frames;
    *p->state = cia402_node_state(n);
}

/* funct cia402.read: take every received frame, supervise the drives, update the feedback pins. */
static void cia402_read(void *arg, long period)
{
    long long now_ns = rtapi_get_time();
    (void)arg;
    for (int b = 0; b < self->bus_count; b++)
        receive_bus(&self->buses[b], now_ns);
    for (int d = 0; d < self->cfg.drive_count; d++) {
        cia402_node_check(&self->nodes[d], now_ns);
        update_pins(d, period);
    }
}

/* funct cia402.write: controlword and target position (or set-up traffic) of every drive, then SYNC. */
static void cia402_write(void *arg, long period)
{
    long long now_ns = rtapi_get_time();
    co_frame_t frames[CIA402_FRAMES_PER_CYCLE];
    co_frame_t sync = { .id = self->cfg.sync_cob_id, .len = 0 };
    (void)arg;
    for (int d = 0; d < self->cfg.drive_count; d++) {
        drive_pins_t *p = &self->pins[d];
        cia402_command_t cmd = { *p->enable, *p->fault_reset, *p->position_cmd };
        int k = cia402_node_transmit(&self->nodes[d], &cmd, now_ns, period, frames);
        for (int i = 0; i < k; i++)
            can_bus_queue(&self->buses[self->bus_of[d]].io, &frames[i]);
        *p->enabled = cia402_node_enabled(&self->nodes[d]);
        *p->fault = self->nodes[d].fault != CIA402_FAULT_NONE;
        *p->fault_code = self->nodes[d].fault;
        *p->controlword = self->nodes[d].controlword;
    }
    for (int b = 0; b < self->bus_count; b++) {
        bus_t *bus = &self->buses[b];
        int r;
        can_bus_queue(&bus->io, &sync);
        r = can_bus_flush(&bus->io);
        if (r != 0 && r != -EAGAIN)
            bus_failed(bus, "send", r);
        *bus->tx_dropped = bus->io.tx_dropped;
    }
}

/* The bus index for interface name, adding it when new. */
static int bus_index(const char *name)
{
    for (int b = 0; b < self->bus_count; b++)
        if (strcmp(self->buses[b].name, name) == 0)
            return b;
    bus_t *bus = &self->buses[self->bus_count];
    memset(bus, 0, sizeof(*bus));
    size_t len = strnlen(name, sizeof(bus->name) - 1);
    memcpy(bus->name, name, len);
    bus->name[len] = '\0';
    bus->io.fd = -1;
    for (int i = 0; i <= CO_MAX_NODE; i++)
        bus->node_of[i] = NO_NODE;
    return self->bus_count++;
}

/* Open every interface with the COB-IDs of its drives; 0 or a negative errno (reported). */
static int open_buses(void)
{
    char why[160];
    for (int d = 0; d < self->cfg.drive_count; d++) {
        const cia402_drive_cfg_t *c = &self->cfg.drives[d];
        self->bus_of[d] = bus_index(c->interface);
        self->buses[self->bus_of[d]].node_of[c->node_id] = d;
    }
    for (int b = 0; b < self->bus_count; b++) {
        uint16_t ids[IDS_PER_NODE * (CO_MAX_NODE + 1)];
        static const uint16_t functions[IDS_PER_NODE] = { CO_EMCY, CO_TPDO1, CO_TPDO2, CO_SDO_TX, CO_HEARTBEAT };
        int count = 0, r;
        for (int node = 1; node <= CO_MAX_NODE; node++)
            for (int f = 0; f < IDS_PER_NODE && self->buses[b].node_of[node] != NO_NODE; f++)
                ids[count++] = (uint16_t)(functions[f] + node);
        r = can_bus_open(&self->buses[b].io, self->buses[b].name, ids, count, why, sizeof(why));
        if (r != 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "cia402: %s\n", why);
            return r;
        }
    }
    return 0;
}

/* Create the pins of drive d. */
static int export_drive(int d)
{
    drive_pins_t *p = &self->pins[d];
    int n = self->cfg.drives[d].number, r = 0;
#define PIN(kind, dir, field, name) if (r == 0) r = hal_pin_##kind##_newf(dir, &p->field, comp_id, "cia402.%d." name, n)
    PIN(bit, HAL_IN, enable, "enable");
    PIN(bit, HAL_IN, fault_reset, "fault-reset");
    PIN(float, HAL_IN, position_cmd, "position-cmd");
    PIN(float, HAL_OUT, position_fb, "position-fb");
    PIN(float, HAL_OUT, velocity_fb, "velocity-fb");
    PIN(float, HAL_OUT, torque_fb, "torque-fb");
    PIN(bit, HAL_OUT, enabled, "enabled");
    PIN(bit, HAL_OUT, fault, "fault");
    PIN(bit, HAL_OUT, ready, "ready");
    PIN(u32, HAL_OUT, fault_code, "fault-code");
    PIN(u32, HAL_OUT, error_code, "error-code");
    PIN(u32, HAL_OUT, statusword, "statusword");
    PIN(u32, HAL_OUT, controlword, "controlword");
    PIN(u32, HAL_OUT, nmt_state, "nmt-state");
    PIN(u32, HAL_OUT, bad_frames, "bad-frames");
    PIN(s32, HAL_OUT, state, "state");
#undef PIN
    if (r == 0)
        *p->state = CIA402_UNKNOWN;
    return r;
}

/* Create every pin and the functs. */
static int export_all(void)
{
    int r = 0;
    self->pins = hal_malloc(sizeof(*self->pins) * self->cfg.drive_count);
    if (!self->pins)
        return -ENOMEM;
    memset(self->pins, 0, sizeof(*self->pins) * self->cfg.drive_count);
    for (int d = 0; d < self->cfg.drive_count && r == 0; d++)
        r = export_drive(d);
    for (int b = 0; b < self->bus_count && r == 0; b++) {
        hal_u32_t **pin = hal_malloc(sizeof(*pin));
        r = pin ? hal_pin_u32_newf(HAL_OUT, pin, comp_id, "cia402.%s.tx-dropped", self->buses[b].name)
                : -ENOMEM;
        if (r == 0)
            self->buses[b].tx_dropped = *pin;
    }
    if (r == 0)
        r = hal_export_funct("cia402.read", cia402_read, NULL, 1, 0, comp_id);
    if (r == 0)
        r = hal_export_funct("cia402.write", cia402_write, NULL, 1, 0, comp_id);
    return r;
}

/* Close the interfaces and free the module's memory. */
static void release(void)
{
    if (!self)
        return;
    for (int b = 0; b < self->bus_count; b++)
        can_bus_close(&self->buses[b].io);
    free(self);
    self = NULL;
}

/* Read the configuration, open the interfaces and create the HAL objects. */
int rtapi_app_main(void)
{
    int r;
    if (!config || !*config) {
        rtapi_print_msg(RTAPI_MSG_ERR, "cia402: config=FILE is required (the drive configuration)\n");
        return -EINVAL;
    }
    self = calloc(1, sizeof(*self));
    if (!self)
        return -ENOMEM;
    r = cia402_cfg_load(&self->cfg, config, config_report, NULL) == 0 ? open_buses() : -EINVAL;
    for (int d = 0; r == 0 && d < self->cfg.drive_count; d++)
        cia402_node_init(&self->nodes[d], &self->cfg.drives[d], self->cfg.path, node_report, NULL);
    if (r == 0) {
        comp_id = hal_init("cia402");
        r = comp_id < 0 ? comp_id : export_all();
    }
    if (r != 0) {
        if (comp_id >= 0)
            hal_exit(comp_id);
        release();
        return r;
    }
    rtapi_print_msg(RTAPI_MSG_INFO, "cia402: %d drive(s) on %d interface(s) from %s\n", self->cfg.drive_count,
                    self->bus_count, self->cfg.path);
    hal_ready(comp_id);
    return 0;
}

/* Leave every drive safe: RPDO1 with Shutdown and a SYNC, then NMT pre-operational. */
static void say_goodbye(void)
{
    co_frame_t rpdo, nmt[CIA402_MAX_DRIVES];
    co_frame_t sync = { .id = self->cfg.sync_cob_id, .len = 0 };
    for (int d = 0; d < self->cfg.drive_count; d++)
        if (cia402_node_goodbye(&self->nodes[d], &rpdo, &nmt[d]))
            can_bus_queue(&self->buses[self->bus_of[d]].io, &rpdo);
    for (int b = 0; b < self->bus_count; b++)
        can_bus_queue(&self->buses[b].io, &sync);
    for (int d = 0; d < self->cfg.drive_count; d++)
        can_bus_queue(&self->buses[self->bus_of[d]].io, &nmt[d]);
    for (int b = 0; b < self->bus_count; b++)
        can_bus_flush(&self->buses[b].io);
}

/* Leave the drives safe, close the interfaces and remove the component. */
void rtapi_app_exit(void)
{
    if (self)
        say_goodbye();
    hal_exit(comp_id);
    release();
}
