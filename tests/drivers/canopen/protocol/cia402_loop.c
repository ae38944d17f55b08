/* cia402_loop.c: the cia402 driver's protocol engine against the simulated drive, joined by an
   in-memory bus with simulated time: set-up, enable, motion, every fault and its recovery. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "cia402_node.h"
#include "sim/sim_drive.h"

#define PERIOD_NS 1000000L
#define QUEUE_MAX 256
#define NODES 2

/* The whole loop: master side, simulated drives, the frames in flight, what to drop. */
typedef struct {
    cia402_drive_cfg_t cfg[NODES];
    cia402_node_t node[NODES];
    sim_drive_t sim[NODES];
    int sim_present[NODES];
    co_frame_t to_master[QUEUE_MAX];
    int queued;
    long long now_ns;
    cia402_command_t cmd[NODES];
    int drop_tpdo1, drop_rpdo1, drop_heartbeat;    /* node ids whose frames are lost, 0 = none */
    int show_sim_log;
} loop_t;

static loop_t L;

/* Master messages. */
static void master_report(void *ctx, int is_error, const char *text)
{
    (void)ctx;
    printf("  master %s: %s\n", is_error ? "error" : "info", text);
}

/* Simulated drive log lines (shown only while show_sim_log is set). */
static void sim_log(void *ctx, const char *text)
{
    (void)ctx;
    if (L.show_sim_log)
        printf("  sim: %s\n", text);
}

/* A drive sends: queue for the master's next read, unless dropped. */
static void sim_send(void *ctx, const co_frame_t *f)
{
    (void)ctx;
    if (f->id == CO_TPDO1 + L.drop_tpdo1 || f->id == CO_HEARTBEAT + L.drop_heartbeat)
        return;
    if (L.queued < QUEUE_MAX)
        L.to_master[L.queued++] = *f;
}

/* The master sends: every present drive receives it at once. */
static void to_drives(const co_frame_t *f)
{
    if (f->id == CO_RPDO1 + L.drop_rpdo1)
        return;
    for (int i = 0; i < NODES; i++)
        if (L.sim_present[i])
            sim_drive_receive(&L.sim[i], f, L.now_ns);
}

/* One servo period: read (deliver, check), write (transmit, SYNC), drives tick. */
static void cycle(void)
{
    co_frame_t frames[CIA402_FRAMES_PER_CYCLE], sync = { .id = CO_SYNC };
    int n = L.queued;
    L.now_ns += PERIOD_NS;
    L.queued = 0;
    for (int k = 0; k < n; k++)
        for (int i = 0; i < NODES; i++)
            if ((int)(L.to_master[k].id & CO_NODE_MASK) == L.cfg[i].node_id && (L.to_master[k].id & CO_FUNC_MASK))
                cia402_node_receive(&L.node[i], &L.to_master[k], L.now_ns);
    for (int i = 0; i < NODES; i++)
        cia402_node_check(&L.node[i], L.now_ns);
    for (int i = 0; i < NODES; i++) {
        int k = cia402_node_transmit(&L.node[i], &L.cmd[i], L.now_ns, PERIOD_NS, frames);
        for (int j = 0; j < k; j++)
            to_drives(&frames[j]);
    }
    to_drives(&sync);
    for (int i = 0; i < NODES; i++)
        if (L.sim_present[i])
            sim_drive_tick(&L.sim[i], L.now_ns);
}

/* Run count cycles. */
static void run(int count)
{
    for (int i = 0; i < count; i++)
        cycle();
}

/* Run until cond(i) holds for drive i (at most limit cycles); prints how long it took, bucketed. */
static void run_until(int i, int (*cond)(int), int limit, const char *what)
{
    int n = 0;
    while (!cond(i) && n < limit) {
        cycle();
        n++;
    }
    printf("drive %d %s: %s\n", i, what, cond(i) ? (n <= 10 ? "within 10 cycles" : n <= 100 ? "within 100 cycles"
                                                    : "within the limit") : "NOT REACHED");
}

static int is_running(int i) { return L.node[i].link == CIA402_LINK_RUNNING; }
static int is_enabled(int i) { return cia402_node_enabled(&L.node[i]); }
static int is_faulted(int i) { return L.node[i].fault != CIA402_FAULT_NONE; }

/* One line of the drive's master-side state. */
static void show(int i)
{
    const cia402_node_t *n = &L.node[i];
    printf("drive %d: link %d fault %d error 0x%04X state %s cw 0x%04X enabled %d position %.4f bad %u\n", i,
           n->link, n->fault, n->error_code, cia402_state_name(cia402_node_state(n)), n->controlword,
           cia402_node_enabled(n), (double)n->position_counts / n->cfg->position_scale, n->bad_frames);
}

/* A drive configuration as the file would give it. */
static void configure(int i, int node_id, double scale)
{
    cia402_drive_cfg_t *c = &L.cfg[i];
    memset(c, 0, sizeof(*c));
    c->number = i;
    c->section_line = 10 * (i + 1);
    c->node_id = node_id;
    c->node_line = c->section_line + 1;
    snprintf(c->interface, sizeof(c->interface), "vcan0");
    c->position_scale = scale;
    c->heartbeat_ms = 100;
    c->heartbeat_timeout_ms = 300;
    c->pdo_timeout_ms = 20;
    c->sdo_timeout_ms = 100;
    c->enable_timeout_ms = 1000;
    c->velocity_feedback = 1;
    c->sync_period_objects = 1;
}

/* Fault reset through a rising edge of fault-reset. */
static void pulse_reset(int i)
{
    L.cmd[i].fault_reset = 1;
    cycle();
    L.cmd[i].fault_reset = 0;
}


/* Start-up: drive 0 configures (its set-up writes listed); drive 1 is absent, then boots. */
static void case_startup(void)
{
    printf("== start-up (drive 1 absent)\n");
    L.sim_present[0] = 1;
    L.show_sim_log = 1;
    sim_drive_boot(&L.sim[0], L.now_ns);
    run_until(0, is_running, 300, "operational");
    L.show_sim_log = 0;
    run(150);
    show(1);
    printf("== drive 1 powers up\n");
    L.sim_present[1] = 1;
    sim_drive_boot(&L.sim[1], L.now_ns);
    run_until(1, is_running, 300, "operational");
    printf("drive 1 vendor object 2000:01 = %u\n", sim_od_get(&L.sim[1].od, 0x2000, 1));
    show(0);
    show(1);
}

/* Enable and move drive 0. */
static void case_motion(void)
{
    printf("== enable and move drive 0\n");
    L.cmd[0].enable = 1;
    run_until(0, is_enabled, 20, "enabled");
    show(0);
    L.cmd[0].position_cmd = 0.05;
    run(3);
    show(0);
    L.cmd[0].position_cmd = 4.0;
    run(5);
    printf("drive 0 moving: velocity %.0f counts/s, torque %.1f %%, target %d\n", (double)L.node[0].velocity_raw,
           L.node[0].torque_raw / 10.0, L.node[0].target);
    run(30);
    show(0);
}

/* An EMCY faults the drive; a fault-reset pulse recovers it. */
static void case_emcy(void)
{
    printf("== EMCY 0x2310 from drive 0\n");
    sim_drive_emcy(&L.sim[0], 0x2310);
    run(3);
    show(0);
    printf("simulated drive 0 is in %s\n", cia402_state_name(L.sim[0].state));
    pulse_reset(0);
    run_until(0, is_enabled, 20, "enabled again");
    show(0);
}

/* Link faults: each is reported once, disables the drive and recovers on a reset. */
static void recover(int i)
{
    pulse_reset(i);
    run_until(i, is_enabled, 300, "reconfigured and enabled");
    show(i);
}

/* Silent, heartbeat lost, reboot, pre-operational, feedback lost. */
static void case_link_faults(void)
{
    printf("== drive 0's heartbeats are lost (PDOs still arrive)\n");
    L.drop_heartbeat = 3;
    run_until(0, is_faulted, 400, "faulted");
    show(0);
    L.drop_heartbeat = 0;
    run(150);
    recover(0);
    printf("== drive 0 goes silent\n");
    L.sim[0].silent = 1;
    run_until(0, is_faulted, 400, "faulted");
    show(0);
    run(100);
    L.sim[0].silent = 0;
    run(5);
    recover(0);
    printf("== drive 0 reboots\n");
    sim_drive_boot(&L.sim[0], L.now_ns);
    run(2);
    show(0);
    recover(0);
    printf("== drive 0 drops to pre-operational\n");
    sim_drive_set_nmt(&L.sim[0], CO_STATE_PRE_OPERATIONAL);
    run_until(0, is_faulted, 150, "faulted");
    show(0);
    recover(0);
    printf("== drive 0's TPDO1 stops\n");
    L.drop_tpdo1 = 3;
    run_until(0, is_faulted, 50, "faulted");
    L.drop_tpdo1 = 0;
    show(0);
    recover(0);
}

/* Malformed frames are counted and reported once; a malformed EMCY is an emergency. */
static void case_malformed(void)
{
    printf("== malformed frames from drive 0\n");
    sim_drive_send_bad(&L.sim[0], SIM_BAD_TPDO1);
    sim_drive_send_bad(&L.sim[0], SIM_BAD_TPDO1);
    sim_drive_send_bad(&L.sim[0], SIM_BAD_HEARTBEAT);
    run(3);
    show(0);
    sim_drive_send_bad(&L.sim[0], SIM_BAD_EMCY);
    run(2);
    show(0);
    recover(0);
}

/* The drive never reaches Operation enabled; a command that is not a number. */
static void case_drive_faults(void)
{
    printf("== drive 0 ignores its controlword\n");
    L.cmd[0].enable = 0;
    run(5);
    L.drop_rpdo1 = 3;
    L.cmd[0].enable = 1;
    run_until(0, is_faulted, 1100, "faulted");
    show(0);
    L.drop_rpdo1 = 0;
    recover(0);
    printf("== position command NaN\n");
    L.cmd[0].position_cmd = NAN;
    run(2);
    show(0);
    L.cmd[0].position_cmd = (double)L.node[0].position_counts / L.cfg[0].position_scale;
    recover(0);
}

/* Set-up refused by the drive (read-only object), then a malformed SDO answer. */
static void case_setup_errors(void)
{
    printf("== drive 1's SDO line writes a read-only object\n");
    L.cfg[1].sdo[0] = (cia402_sdo_item_t){ { 0x2001, 0, 4, 5 }, 16 };
    cia402_node_init(&L.node[1], &L.cfg[1], "drives.ini", master_report, NULL);
    run_until(1, is_faulted, 300, "faulted");
    show(1);
    printf("== drive 1 answers an SDO with a short frame\n");
    L.cfg[1].sdo_count = 0;
    sim_drive_send_bad(&L.sim[1], SIM_BAD_SDO);
    cia402_node_init(&L.node[1], &L.cfg[1], "drives.ini", master_report, NULL);
    run_until(1, is_faulted, 300, "faulted");
    show(1);
    L.cmd[1].enable = 1;
    recover(1);
}

/* Drive 1 (1 count per unit) crosses the 32-bit position wrap. */
static void case_wrap(void)
{
    printf("== drive 1 crosses 2^31 counts\n");
    L.sim[1].max_speed = 1e12;
    L.cmd[1].position_cmd = 2147483000.0;
    run(3);
    show(1);
    L.cmd[1].position_cmd = 2147484000.0;
    run(3);
    show(1);
    printf("raw position %d, target %d\n", L.node[1].position_raw, L.node[1].target);
}

/* Every case in order. */
static void run_cases(void)
{
    case_startup();
    case_motion();
    case_emcy();
    case_link_faults();
    case_malformed();
    case_drive_faults();
    case_setup_errors();
    case_wrap();
}

int main(void)
{
    configure(0, 3, 1000.0);
    configure(1, 5, 1.0);
    L.cfg[1].sdo[0] = (cia402_sdo_item_t){ { 0x2000, 1, 4, 1234 }, 15 };
    L.cfg[1].sdo_count = 1;
    for (int i = 0; i < NODES; i++) {
        cia402_node_init(&L.node[i], &L.cfg[i], "drives.ini", master_report, NULL);
        sim_drive_init(&L.sim[i], L.cfg[i].node_id, 200000.0, sim_send, sim_log, NULL);
    }
    L.now_ns = 1000 * PERIOD_NS;
    run_cases();
    return 0;
}
