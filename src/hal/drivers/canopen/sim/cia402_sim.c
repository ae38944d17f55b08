/* cia402_sim.c: cia402-sim, simulated CiA 402 drives on a SocketCAN interface (vcan) for testing
   the cia402 driver; commands on standard input inject faults. */
#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "../can_bus.h"
#include "sim_drive.h"

#define SIM_MAX_NODES 8
#define POLL_MAX_MS 50
#define DEFAULT_SPEED 200000.0

/* The program: its bus, its drives and the log file. */
typedef struct {
    can_bus_t bus;
    sim_drive_t drives[SIM_MAX_NODES];
    int count;
    FILE *log;
} sim_t;

/* Monotonic time in ns. */
static long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Frame sink of the drives: send at once. */
static void send_frame(void *ctx, const co_frame_t *f)
{
    sim_t *s = ctx;
    can_bus_queue(&s->bus, f);
    if (can_bus_flush(&s->bus) != 0)
        fprintf(stderr, "cia402-sim: send failed: %s\n", strerror(s->bus.last_errno ? s->bus.last_errno : EAGAIN));
}

/* Log sink of the drives. */
static void log_line(void *ctx, const char *text)
{
    sim_t *s = ctx;
    fprintf(s->log, "%s\n", text);
    fflush(s->log);
}

/* Print the usage text. */
static void usage(FILE *out)
{
    fprintf(out, "Usage: cia402-sim [--interface IF] --node N [--node N]... [--max-speed COUNTS_PER_S] [--log FILE]\n"
                 "Simulated CiA 402 drives on SocketCAN interface IF (default vcan0).\n"
                 "Commands on standard input: emcy N CODE | silence N | resume N | reboot N |\n"
                 "  nmt N preop|stop|op | bad N tpdo|heartbeat|emcy|sdo | status N | quit\n");
}

/* The drive with node id node, or NULL. */
static sim_drive_t *drive_of(sim_t *s, int node)
{
    for (int i = 0; i < s->count; i++)
        if (s->drives[i].node_id == node)
            return &s->drives[i];
    return NULL;
}

/* Print one drive's state on standard output. */
static void print_status(sim_drive_t *d)
{
    printf("node %d: nmt 0x%02X state %s position %d target %d mode %d heartbeat %u\n", d->node_id, d->nmt,
           cia402_state_name(d->state), (int32_t)sim_od_get(&d->od, CIA402_POSITION_ACTUAL, 0),
           (int32_t)sim_od_get(&d->od, CIA402_TARGET_POSITION, 0), (int8_t)sim_od_get(&d->od, CIA402_MODE, 0),
           sim_od_get(&d->od, CO_OBJ_HEARTBEAT_TIME, 0));
    fflush(stdout);
}

/* Apply a word argument command (nmt, bad); 0 or -1. */
static int word_command(sim_drive_t *d, const char *cmd, const char *word)
{
    static const struct { const char *word; uint8_t state; } nmt[] = {
        { "preop", CO_STATE_PRE_OPERATIONAL }, { "stop", CO_STATE_STOPPED }, { "op", CO_STATE_OPERATIONAL } };
    static const char *const bad[] = { "tpdo", "heartbeat", "emcy", "sdo" };
    for (unsigned i = 0; strcmp(cmd, "nmt") == 0 && i < sizeof(nmt) / sizeof(nmt[0]); i++)
        if (strcmp(word, nmt[i].word) == 0) {
            sim_drive_set_nmt(d, nmt[i].state);
            return 0;
        }
    for (unsigned i = 0; strcmp(cmd, "bad") == 0 && i < sizeof(bad) / sizeof(bad[0]); i++)
        if (strcmp(word, bad[i]) == 0) {
            sim_drive_send_bad(d, (sim_bad_kind_t)i);
            return 0;
        }
    return -1;
}

/* Run one command line; returns 1 for quit, 0 otherwise (errors go to stderr). */
static int command(sim_t *s, char *line)
{
    char cmd[16] = "", word[32] = "";
    int node = 0, n = sscanf(line, "%15s %d %31s", cmd, &node, word);
    sim_drive_t *d;
    if (n < 1)
        return 0;
    if (strcmp(cmd, "quit") == 0)
        return 1;
    d = n >= 2 ? drive_of(s, node) : NULL;
    if (!d) {
        fprintf(stderr, "cia402-sim: %s: no such node\n", line);
        return 0;
    }
    if (strcmp(cmd, "emcy") == 0 && n == 3)
        sim_drive_emcy(d, (uint16_t)strtoul(word, NULL, 0));
    else if (strcmp(cmd, "silence") == 0 || strcmp(cmd, "resume") == 0)
        d->silent = strcmp(cmd, "silence") == 0;
    else if (strcmp(cmd, "reboot") == 0)
        sim_drive_boot(d, now_ns());
    else if (strcmp(cmd, "status") == 0)
        print_status(d);
    else if (n < 3 || word_command(d, cmd, word) != 0)
        fprintf(stderr, "cia402-sim: unknown command: %s\n", line);
    return 0;
}

/* Read the command lines waiting on standard input; returns 1 at quit or end of input. */
static int read_commands(sim_t *s)
{
    static char buffer[512];
    static size_t used;
    ssize_t got = read(0, buffer + used, sizeof(buffer) - 1 - used);
    char *start = buffer, *nl;
    if (got <= 0)
        return 1;
    used += (size_t)got;
    buffer[used] = '\0';
    while ((nl = strchr(start, '\n'))) {
        *nl = '\0';
        if (command(s, start))
            return 1;
        start = nl + 1;
    }
    used -= (size_t)(start - buffer);
    memmove(buffer, start, used);
    if (used == sizeof(buffer) - 1)
        used = 0;
    return 0;
}

/* Hand every received frame to every drive. */
static void read_frames(sim_t *s)
{
    co_frame_t frames[CAN_BUS_BATCH];
    int valid, got;
    do {
        got = can_bus_receive(&s->bus, frames, CAN_BUS_BATCH, &valid);
        for (int i = 0; i < valid; i++)
            for (int k = 0; k < s->count; k++)
                sim_drive_receive(&s->drives[k], &frames[i], now_ns());
    } while (got == CAN_BUS_BATCH);
}

/* How long poll may sleep: until the next heartbeat is due (1 to POLL_MAX_MS ms). */
static int poll_timeout_ms(const sim_t *s)
{
    long long now = now_ns(), wait_ms = POLL_MAX_MS;
    for (int i = 0; i < s->count; i++) {
        long long due = s->drives[i].next_heartbeat_ns;
        if (due && (due - now) / 1000000 < wait_ms)
            wait_ms = (due - now) / 1000000;
    }
    return wait_ms < 1 ? 1 : (int)wait_ms;
}

/* Parse the options; returns the interface name or NULL after printing why. */
static const char *parse_options(sim_t *s, int argc, char **argv, double *speed)
{
    const char *iface = "vcan0";
    for (int i = 1; i < argc; i++) {
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            exit(0);
        } else if (strcmp(argv[i], "--interface") == 0 && next) {
            iface = argv[++i];
        } else if (strcmp(argv[i], "--node") == 0 && next && s->count < SIM_MAX_NODES &&
                   atoi(next) >= 1 && atoi(next) <= CO_MAX_NODE) {
            s->drives[s->count++].node_id = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--max-speed") == 0 && next && atof(next) > 0) {
            *speed = atof(argv[++i]);
        } else if (strcmp(argv[i], "--log") == 0 && next) {
            if (!(s->log = fopen(argv[++i], "a"))) {
                fprintf(stderr, "cia402-sim: %s: %s\n", argv[i], strerror(errno));
                return NULL;
            }
        } else {
            fprintf(stderr, "cia402-sim: bad argument '%s'\n", argv[i]);
            usage(stderr);
            return NULL;
        }
    }
    if (s->count == 0) {
        usage(stderr);
        return NULL;
    }
    return iface;
}

int main(int argc, char **argv)
{
    static sim_t s;
    char why[160];
    double speed = DEFAULT_SPEED;
    const char *iface;
    s.log = stdout;
    iface = parse_options(&s, argc, argv, &speed);
    if (!iface)
        return 2;
    if (can_bus_open(&s.bus, iface, NULL, 0, why, sizeof(why)) != 0) {
        fprintf(stderr, "cia402-sim: %s\n", why);
        return 1;
    }
    for (int i = 0; i < s.count; i++) {
        sim_drive_init(&s.drives[i], s.drives[i].node_id, speed, send_frame, log_line, &s);
        sim_drive_boot(&s.drives[i], now_ns());
    }
    printf("ready\n");
    fflush(stdout);
    for (;;) {
        struct pollfd fds[2] = { { .fd = s.bus.fd, .events = POLLIN }, { .fd = 0, .events = POLLIN } };
        if (poll(fds, 2, poll_timeout_ms(&s)) < 0 && errno != EINTR)
            break;
        if (fds[0].revents & POLLIN)
            read_frames(&s);
        if ((fds[1].revents & (POLLIN | POLLHUP)) && read_commands(&s))
            break;
        for (int i = 0; i < s.count; i++)
            sim_drive_tick(&s.drives[i], now_ns());
    }
    can_bus_close(&s.bus);
    return 0;
}
