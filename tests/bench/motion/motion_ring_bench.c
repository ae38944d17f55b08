/* motion_ring_bench.c: how fast SET_LINE commands reach the planner through the ring (1 kHz servo thread). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "motion_client.h"

#define BURST 2000          /* the planner queue's size */
#define SUSTAIN_S 3.0

/* Seconds on the monotonic clock. */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Send one command and wait for its echo; 0 or -1. */
static int send(emcmot_client_t *c, emcmot_command_t *cmd)
{
    int result;
    char reason[EMCMOT_REASON_LEN];

    if (emcmot_send(c, cmd, 5.0, &result, reason, sizeof reason) < 0 || result != 0) {
        fprintf(stderr, "motion bench: %s refused: %s\n", emcmot_command_name(cmd->command), reason);
        return -1;
    }
    return 0;
}

/* A short feed move along X to x. */
static void line_to(emcmot_command_t *cmd, double x, int id)
{
    emcmot_command_init(cmd, EMCMOT_SET_LINE);
    cmd->pos.tran.x = x;
    cmd->vel = 100.0;
    cmd->ini_maxvel = 100.0;
    cmd->acc = 1000.0;
    cmd->motion_type = 2;
    cmd->id = id;
}

/* Enable, coordinated mode, wide limits on the nine axes. */
static int setup(emcmot_client_t *c)
{
    static const emcmot_command_code_t codes[] = { EMCMOT_ENABLE, EMCMOT_COORD };
    emcmot_command_t cmd;
    emcmot_status_t st;

    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        emcmot_command_init(&cmd, codes[i]);
        if (send(c, &cmd) < 0)
            return -1;
    }
    for (int i = 0; i < 5000; i++) {
        if (emcmot_read_status(c, &st) == 0 && st.coord)
            return 0;
        usleep(1000);
    }
    fprintf(stderr, "motion bench: no coordinated mode\n");
    return -1;
}

/* Push cmd, spinning while the ring is full; the serial or 0. */
static uint32_t push(emcmot_client_t *c, emcmot_command_t *cmd)
{
    long serial;

    while ((serial = emcmot_push(c, cmd)) == -EAGAIN)
        ;
    return serial > 0 ? (uint32_t)serial : 0;
}

/* BURST segments into an empty planner queue: ring plus command handler throughput. */
static void burst(emcmot_client_t *c)
{
    emcmot_command_t cmd;
    uint32_t last = 0;
    int result;
    double t0 = now_s(), t1;

    for (int i = 1; i <= BURST; i++) {
        line_to(&cmd, i * 1e-4, i);
        last = push(c, &cmd);
    }
    emcmot_wait_serial(c, last, 10.0, &result, NULL, 0);
    t1 = now_s();
    printf("motion: %d segments into the planner in %.1f ms: %.0f segments/s (%.1f per 1 ms servo cycle)\n",
           BURST, (t1 - t0) * 1e3, BURST / (t1 - t0), BURST / (t1 - t0) / 1000.0);
}

/* Abort and wait until the queue is empty. */
static void drain(emcmot_client_t *c)
{
    emcmot_command_t cmd;
    emcmot_status_t st;

    emcmot_command_init(&cmd, EMCMOT_ABORT);
    send(c, &cmd);
    for (int i = 0; i < 10000; i++) {
        if (emcmot_read_status(c, &st) == 0 && st.queue_depth == 0 && st.inpos)
            return;
        usleep(1000);
    }
}

/* Keep the ring full for SUSTAIN_S seconds while the planner executes the segments. */
static void sustained(emcmot_client_t *c)
{
    emcmot_command_t cmd;
    emcmot_status_t a, b;
    double t0, t1, x = 0.0;
    int id = 0;

    emcmot_read_status(c, &a);
    x = a.carte_pos_cmd.tran.x;
    t0 = now_s();
    while (now_s() - t0 < SUSTAIN_S) {
        x += 1e-4;
        line_to(&cmd, x, ++id);
        push(c, &cmd);
    }
    emcmot_read_status(c, &b);
    t1 = now_s();
    printf("motion: sustained %.1f s of 1e-4 unit segments at 100 units/s: %.0f segments/s handled "
           "(the planner's execution rate bounds this once its queue is full)\n",
           t1 - t0, (b.echo.handled - a.echo.handled) / (t1 - t0));
}

int main(void)
{
    emcmot_client_t *c;
    char why[256];

    if (emcmot_attach(0, EMCMOT_ATTACH_PRODUCER, &c, why, sizeof why) < 0) {
        fprintf(stderr, "motion bench: %s\n", why);
        return 1;
    }
    if (setup(c) < 0)
        return 1;
    burst(c);
    drain(c);
    sustained(c);
    drain(c);
    emcmot_detach(c);
    return 0;
}
