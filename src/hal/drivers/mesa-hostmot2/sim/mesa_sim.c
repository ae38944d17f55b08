/* mesa_sim.c: mesa-sim, a simulated Mesa Ethernet card answering LBP16 on a (loopback) UDP address. */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>
#include "sim_card.h"
#include "../lbp16.h"

#define TICK_MS 1
#define LINE_MAX_BYTES 256

static volatile sig_atomic_t stop_requested;

typedef struct {
    const char *ip;
    int port;
} sim_options_t;

/* One flushed line on stdout. */
void sim_say(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
    fflush(stdout);
}

/* Monotonic time in ns. */
static long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Usage: on stdout with exit 0 for --help, on stderr with exit 2 after a bad option. */
static void usage(const char *why)
{
    FILE *out = why ? stderr : stdout;
    if (why)
        fprintf(stderr, "mesa-sim: %s\n", why);
    fprintf(out, "usage: mesa-sim [--board NAME] [--ip ADDR] [--port N] [--mac XX:XX:XX:XX:XX:XX]\n"
                 "                [--loop stepgenS:encoderE[:COUNTS_PER_STEP]]\n"
                 "                [--motor pwmgenP:encoderE:COUNTS_PER_S] [--index encoderE:COUNTS]\n"
                 "                [--remote CHANNEL:7i76|7i77[:UNIT] | --remote CHANNEL:none]\n"
                 "A simulated Mesa Ethernet card answering LBP16 on ADDR (default 127.0.0.1) port N\n"
                 "(default 27181); commands on stdin (see mesa-sim(1)).\nboards:");
    sim_list_boards(out);
    exit(why ? 2 : 0);
}

/* "stepgen2" -> 2 when the prefix matches and the index is below limit, else -1. */
static int unit_of(const char *text, const char *prefix, int limit)
{
    size_t n = strlen(prefix);
    char *end;
    if (strncmp(text, prefix, n) != 0)
        return -1;
    long v = strtol(text + n, &end, 10);
    return (end == text + n || v < 0 || v >= limit) ? -1 : (int)v;
}

/* --loop, --motor, --index: "a:b[:x]" wiring of the simulated machine. */
static void parse_wiring(sim_card_t *c, const char *opt, const char *arg)
{
    char buf[128], msg[192];
    snprintf(buf, sizeof(buf), "%s", arg);
    char *a = strtok(buf, ":"), *b = strtok(NULL, ":"), *x = strtok(NULL, ":");
    const sim_board_t *bd = c->board;
    snprintf(msg, sizeof(msg), "%s '%s': not valid for board %s", opt, arg, bd->name);
    if (!a || !b || c->num_loops >= SIM_MAX_LOOPS)
        usage(msg);
    if (!strcmp(opt, "--index")) {
        int e = unit_of(a, "encoder", bd->encoders);
        if (e < 0 || atoi(b) <= 0)
            usage(msg);
        c->encoder[e].index_every = atoi(b);
        return;
    }
    sim_loop_t *l = &c->loops[c->num_loops];
    bool motor = !strcmp(opt, "--motor");
    l->kind = motor ? SIM_LOOP_MOTOR : SIM_LOOP_STEPGEN;
    l->from = unit_of(a, motor ? "pwmgen" : "stepgen", motor ? bd->pwmgens : bd->stepgens);
    l->to = unit_of(b, "encoder", bd->encoders);
    l->gain = x ? strtod(x, NULL) : 1.0;
    if (l->from < 0 || l->to < 0 || (motor && !x) || l->gain == 0.0)
        usage(msg);
    c->num_loops++;
}

/* --remote CH:TYPE[:UNIT]: a Smart Serial remote (7i76) or none on a channel of the board's port. */
static void parse_remote(sim_card_t *c, const char *arg)
{
    char buf[64], msg[128];
    snprintf(buf, sizeof(buf), "%s", arg);
    char *ch = strtok(buf, ":"), *type = strtok(NULL, ":"), *unit = strtok(NULL, ":");
    int n = ch ? unit_of(ch, "", c->board->sserial_channels) : -1;
    snprintf(msg, sizeof(msg), "--remote '%s': board %s has %d Smart Serial channels; types: 7i76, 7i77 (two channels), none",
             arg, c->board->name, c->board->sserial_channels);
    if (n < 0 || !type)
        usage(msg);
    if (!strcmp(type, "none")) {
        memset(&c->sserial.remote[n], 0, sizeof(c->sserial.remote[n]));
        return;
    }
    const sim_remote_type_t *t = sim_remote_type(type);
    bool two = !strcasecmp(type, "7i77");
    if (!t || !strcasecmp(type, "7i77-analog") || (two && n + 1 >= c->board->sserial_channels))
        usage(msg);
    uint32_t u = unit ? (uint32_t)strtoul(unit, NULL, 0) : 0x10000176u + n;
    sim_remote_attach(&c->sserial.remote[n], t, u);
    if (two)
        sim_remote_attach(&c->sserial.remote[n + 1], sim_remote_type("7i77-analog"), u);
}

/* The board's own remotes: a 7I76E carries its 7I76 field I/O on channel 0, the 7I92 variant
   a 7I77 on channels 0 (field I/O) and 1 (analog outputs). */
static void default_remotes(sim_card_t *c)
{
    if (c->board->sserial_channels && c->board->variant) {
        sim_remote_attach(&c->sserial.remote[0], sim_remote_type("7i77"), 0x10000177u);
        sim_remote_attach(&c->sserial.remote[1], sim_remote_type("7i77-analog"), 0x10000177u);
    } else if (c->board->sserial_channels) {
        sim_remote_attach(&c->sserial.remote[0], sim_remote_type("7i76"), 0x10000176u);
    }
}

/* Command-line options. */
static void parse_args(sim_card_t *c, sim_options_t *o, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *opt = argv[i], *arg = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(opt, "-h") || !strcmp(opt, "--help"))
            usage(NULL);
        if (!arg) {
            char msg[96];
            snprintf(msg, sizeof(msg), "option '%s' needs a value", opt);
            usage(msg);
        }
        i++;
        if (!strcmp(opt, "--board")) {
            if (!(c->board = sim_find_board(arg)))
                usage("unknown --board");
            memset(&c->sserial, 0, sizeof(c->sserial));
            default_remotes(c);
        } else if (!strcmp(opt, "--remote")) {
            parse_remote(c, arg);
        } else if (!strcmp(opt, "--ip")) {
            o->ip = arg;
        } else if (!strcmp(opt, "--port")) {
            o->port = atoi(arg);
        } else if (!strcmp(opt, "--mac")) {
            unsigned m[6];
            if (sscanf(arg, "%x:%x:%x:%x:%x:%x", &m[0], &m[1], &m[2], &m[3], &m[4], &m[5]) != 6)
                usage("--mac needs XX:XX:XX:XX:XX:XX");
            for (int k = 0; k < 6; k++)
                c->mac[k] = (uint8_t)m[k];
        } else if (!strcmp(opt, "--loop") || !strcmp(opt, "--motor") || !strcmp(opt, "--index")) {
            parse_wiring(c, opt, arg);
        } else {
            char msg[96];
            snprintf(msg, sizeof(msg), "unknown option '%s'", opt);
            usage(msg);
        }
    }
}

/* A UDP socket bound to ip:port. */
static int open_socket(const sim_options_t *o)
{
    struct sockaddr_in a = {0};
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)o->port);
    if (inet_pton(AF_INET, o->ip, &a.sin_addr) != 1) {
        fprintf(stderr, "mesa-sim: --ip '%s' is not an IPv4 address\n", o->ip);
        return -1;
    }
    int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    int on = 1;
    if (fd >= 0)
        setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on));
    if (fd < 0 || bind(fd, (struct sockaddr *)&a, sizeof(a)) < 0) {
        fprintf(stderr, "mesa-sim: cannot bind %s:%d: %s\n", o->ip, o->port, strerror(errno));
        if (fd >= 0)
            close(fd);
        return -1;
    }
    return fd;
}

/* Kernel receive time (CLOCK_REALTIME) of a datagram as a monotonic time. */
static long long arrival_time(struct msghdr *msg)
{
    struct timespec real, mono;
    for (struct cmsghdr *cm = CMSG_FIRSTHDR(msg); cm; cm = CMSG_NXTHDR(msg, cm)) {
        if (cm->cmsg_level != SOL_SOCKET || cm->cmsg_type != SCM_TIMESTAMPNS)
            continue;
        struct timespec ts;
        memcpy(&ts, CMSG_DATA(cm), sizeof(ts));
        clock_gettime(CLOCK_REALTIME, &real);
        clock_gettime(CLOCK_MONOTONIC, &mono);
        long long age = (real.tv_sec - ts.tv_sec) * 1000000000LL + (real.tv_nsec - ts.tv_nsec);
        return mono.tv_sec * 1000000000LL + mono.tv_nsec - (age > 0 ? age : 0);
    }
    return now_ns();
}

/* One datagram with the time it arrived, so a descheduled simulator still sees when pets came. */
static ssize_t receive_stamped(int fd, uint8_t *buf, size_t cap, struct sockaddr_in *from, long long *at)
{
    char control[256];
    struct iovec iov = {buf, cap};
    struct msghdr msg = {0};
    msg.msg_name = from;
    msg.msg_namelen = sizeof(*from);
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof(control);
    ssize_t n = recvmsg(fd, &msg, MSG_DONTWAIT);
    if (n >= 0)
        *at = arrival_time(&msg);
    return n;
}

/* Answer one datagram (with the injected faults). */
static bool serve_datagram(sim_card_t *c, int fd)
{
    uint8_t in[2048], out[LBP16_MAX_PACKET + 64];
    struct sockaddr_in from;
    socklen_t fromlen = sizeof(from);
    long long arrival;
    ssize_t n = receive_stamped(fd, in, sizeof(in), &from, &arrival);
    if (n < 0)
        return false;
    fromlen = sizeof(from);
    sim_advance(c, arrival);
    c->rx_packets++;
    if (c->paused) {
        c->dropped++;
        return true;
    }
    int reply = sim_handle_datagram(c, in, (int)n, out, LBP16_MAX_PACKET);
    if (reply <= 0)
        return true;
    if (c->drop_replies > 0) {
        c->drop_replies--;
        c->dropped++;
        return true;
    }
    if (c->garble_replies > 0) {
        c->garble_replies--;
        reply--;
    } else if (c->stale_replies > 0 && reply >= 8) {
        c->stale_replies--;
        out[reply - 8] ^= 0x55;
    }
    if (c->reply_delay_ns > 0) {
        struct timespec ts = {c->reply_delay_ns / 1000000000LL, c->reply_delay_ns % 1000000000LL};
        nanosleep(&ts, NULL);
    }
    if (sendto(fd, out, reply, 0, (struct sockaddr *)&from, fromlen) == reply)
        c->tx_packets++;
    return true;
}

/* Read available stdin bytes and run complete lines; 1 = quit. */
static int serve_stdin(sim_card_t *c, char *line, size_t *used, bool *open)
{
    ssize_t n = read(0, line + *used, LINE_MAX_BYTES - 1 - *used);
    if (n <= 0) {
        *open = false;
        return 0;
    }
    *used += (size_t)n;
    line[*used] = '\0';
    char *nl;
    while ((nl = strchr(line, '\n'))) {
        *nl = '\0';
        int r = sim_command(c, line);
        size_t rest = *used - (size_t)(nl + 1 - line);
        memmove(line, nl + 1, rest + 1);
        *used = rest;
        if (r)
            return 1;
    }
    if (*used >= LINE_MAX_BYTES - 1)
        *used = 0;
    return 0;
}

/* SIGTERM / SIGINT end the main loop. */
static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

/* Serve datagrams and commands until quit, EOF-less signal or error. */
int main(int argc, char **argv)
{
    static sim_card_t card;
    sim_options_t opt = {"127.0.0.1", LBP16_UDP_PORT};
    uint8_t default_mac[6] = {0x00, 0x60, 0x1b, 0x11, 0x00, 0x01};
    card.board = sim_find_board("7i92");
    memcpy(card.mac, default_mac, 6);
    parse_args(&card, &opt, argc, argv);
    memset(card.input_level, 1, sizeof(card.input_level));
    card.wd_timer = 0x80000000u;
    card.stepgen_master_dds = 0xFFFFFFFFu;
    sim_build_rom(&card);
    card.start_ns = card.now_ns = now_ns();
    int fd = open_socket(&opt);
    if (fd < 0)
        return 1;
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    signal(SIGPIPE, SIG_IGN);
    sim_say("ready %s %d %s", opt.ip, opt.port, card.board->name);
    char line[LINE_MAX_BYTES];
    size_t used = 0;
    bool stdin_open = true;
    while (!stop_requested) {
        struct pollfd p[2] = {{fd, POLLIN, 0}, {0, POLLIN, 0}};
        int r = poll(p, stdin_open ? 2 : 1, TICK_MS);
        if (r > 0 && (p[0].revents & POLLIN))
            while (serve_datagram(&card, fd))
                ;
        sim_advance(&card, now_ns());
        if (r > 0 && stdin_open && (p[1].revents & (POLLIN | POLLHUP)) &&
            serve_stdin(&card, line, &used, &stdin_open))
            break;
    }
    close(fd);
    return 0;
}
