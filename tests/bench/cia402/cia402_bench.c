/* cia402_bench.c: time one servo cycle of the cia402 engine (frames in, supervision, frames out)
   for 1, 8 and 32 running drives in Operation enabled; prints p50, p99 and max in ns. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "cia402_node.h"

#define CYCLES 20000
#define PERIOD_NS 1000000L
#define MAX_DRIVES 32
#define SETUP_LIMIT 1000

static cia402_drive_cfg_t cfg[MAX_DRIVES];
static cia402_node_t nodes[MAX_DRIVES];
static long long cycle_ns[CYCLES];

/* Messages are not part of the measurement. */
static void quiet(void *ctx, int is_error, const char *text)
{
    (void)ctx; (void)is_error; (void)text;
}

/* Monotonic time in ns. */
static long long now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* A frame from node id with function code func and data. */
static co_frame_t frame(unsigned func, int id, int len, uint16_t a, uint32_t b)
{
    co_frame_t f = { .id = (uint16_t)(func + id), .len = (uint8_t)len };
    co_put16(f.data, a);
    co_put32(&f.data[2], b);
    return f;
}

/* Answer every set-up request of drive d until it runs. */
static void bring_up(int d, long long *t)
{
    cia402_command_t cmd = { 1, 0, 0.0 };
    co_frame_t out[CIA402_FRAMES_PER_CYCLE];
    for (int i = 0; i < SETUP_LIMIT && nodes[d].link != CIA402_LINK_RUNNING; i++) {
        *t += PERIOD_NS;
        int k = cia402_node_transmit(&nodes[d], &cmd, *t, PERIOD_NS, out);
        if (k && (out[0].id & CO_FUNC_MASK) == CO_SDO_RX) {
            co_frame_t reply = out[0];
            reply.id = (uint16_t)(CO_SDO_TX + cfg[d].node_id);
            reply.data[0] = CO_SDO_SCS_DOWNLOAD;
            cia402_node_receive(&nodes[d], &reply, *t);
        }
        if (nodes[d].link == CIA402_LINK_STARTING) {
            co_frame_t beat = { .id = (uint16_t)(CO_HEARTBEAT + cfg[d].node_id), .len = 1,
                                .data = { CO_STATE_OPERATIONAL } };
            cia402_node_receive(&nodes[d], &beat, *t);
        }
    }
}

/* Sort helper for the percentiles. */
static int by_value(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = *(const long long *)b;
    return (x > y) - (x < y);
}

/* Time CYCLES cycles of n drives. */
static void measure(int n)
{
    long long t = 1000 * PERIOD_NS;
    co_frame_t out[CIA402_FRAMES_PER_CYCLE];
    for (int d = 0; d < n; d++) {
        memset(&cfg[d], 0, sizeof(cfg[d]));
        cfg[d] = (cia402_drive_cfg_t){ .number = d, .node_id = d + 1, .position_scale = 1000.0,
                                       .heartbeat_ms = 100, .heartbeat_timeout_ms = 300, .pdo_timeout_ms = 20,
                                       .sdo_timeout_ms = 100, .enable_timeout_ms = 1000, .velocity_feedback = 1,
                                       .sync_period_objects = 1 };
        snprintf(cfg[d].interface, sizeof(cfg[d].interface), "can0");
        cia402_node_init(&nodes[d], &cfg[d], "bench.ini", quiet, NULL);
        bring_up(d, &t);
    }
    for (int c = 0; c < CYCLES; c++) {
        long long t0 = now();
        t += PERIOD_NS;
        for (int d = 0; d < n; d++) {
            co_frame_t tpdo1 = frame(CO_TPDO1, d + 1, 6, 0x0637, (uint32_t)c);
            co_frame_t tpdo2 = frame(CO_TPDO2, d + 1, 6, 0, 1000);
            cia402_command_t cmd = { 1, 0, c / 1000.0 };
            cia402_node_receive(&nodes[d], &tpdo1, t);
            cia402_node_receive(&nodes[d], &tpdo2, t);
            if (c % 100 == 0) {
                co_frame_t beat = { .id = (uint16_t)(CO_HEARTBEAT + d + 1), .len = 1, .data = { CO_STATE_OPERATIONAL } };
                cia402_node_receive(&nodes[d], &beat, t);
            }
            cia402_node_check(&nodes[d], t);
            cia402_node_transmit(&nodes[d], &cmd, t, PERIOD_NS, out);
        }
        cycle_ns[c] = now() - t0;
    }
    int enabled = 0;
    for (int d = 0; d < n; d++)
        enabled += cia402_node_enabled(&nodes[d]);
    qsort(cycle_ns, CYCLES, sizeof(cycle_ns[0]), by_value);
    printf("cia402: engine per cycle (no socket I/O), %d drive(s) enabled of %d, %d cycles: p50 %lld ns, "
           "p99 %lld ns, max %lld ns\n", enabled, n, CYCLES, cycle_ns[CYCLES / 2], cycle_ns[CYCLES * 99 / 100],
           cycle_ns[CYCLES - 1]);
}

int main(void)
{
    measure(1);
    measure(8);
    measure(32);
    return 0;
}
