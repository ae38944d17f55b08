/* modbus_sim.c: simulated Modbus device (TCP, or RTU on a pty) with coils, discrete inputs and registers, for tests. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <modbus.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#define MAX_CLIENTS 32

/* Command line settings and run-time state of the simulator. */
typedef struct {
    const char *bind_addr;
    int port;
    int ncoils, ndi, nhr, nir;
    FILE *log;
    modbus_mapping_t *map;
    int clients[MAX_CLIENTS];
    int nclients;
    int stdin_open;
    int rtu_slave;      /* -1: serve TCP; else the RTU slave id served on a pty */
    int rtu_fd;         /* pty master of the RTU device, or -1 */
    int pty_keep_fd;    /* our own open of the pty slave, so the master never sees EIO */
} sim_t;

/* Prints the usage text to out and returns status. */
static int usage_to(FILE *out, int status)
{
    fprintf(out, "usage: modbus-sim [--bind ADDR] [--port N] [--coils N] [--discrete N] "
                    "[--holding N] [--input N] [--set TABLE:ADDR=VALUE]... [--log FILE] [--rtu SLAVE]\n"
                    "TABLE is coil, di, hr or ir; port 0 picks a free port, printed as 'port N'.\n"
                    "--rtu serves Modbus RTU as SLAVE on a new pty, printed as 'pty PATH'.\n"
                    "stdin takes commands 'set TABLE ADDR VALUE' and 'quit'.\n");
    return status;
}

/* Prints the usage text on stderr and returns 1. */
static int usage(void)
{
    return usage_to(stderr, 1);
}

/* Parses a non-negative integer up to max; -1 when bad. */
static long parse_num(const char *s, long max)
{
    char *end;
    long v = strtol(s, &end, 0);
    return (*s && *end == '\0' && v >= 0 && v <= max) ? v : -1;
}

/* Stores value at addr of the named table; 0 or -1 with a message. */
static int set_value(sim_t *sim, const char *table, long addr, long value)
{
    modbus_mapping_t *m = sim->map;
    if (!strcmp(table, "coil") && addr < m->nb_bits && value <= 1)
        m->tab_bits[addr] = (uint8_t)value;
    else if (!strcmp(table, "di") && addr < m->nb_input_bits && value <= 1)
        m->tab_input_bits[addr] = (uint8_t)value;
    else if (!strcmp(table, "hr") && addr < m->nb_registers && value <= 65535)
        m->tab_registers[addr] = (uint16_t)value;
    else if (!strcmp(table, "ir") && addr < m->nb_input_registers && value <= 65535)
        m->tab_input_registers[addr] = (uint16_t)value;
    else {
        fprintf(stderr, "modbus-sim: bad set '%s %ld %ld' (table, address or value out of range)\n",
                table, addr, value);
        return -1;
    }
    return 0;
}

/* Applies "--set TABLE:ADDR=VALUE". */
static int set_option(sim_t *sim, char *arg)
{
    char *colon = strchr(arg, ':'), *eq = strchr(arg, '=');
    if (!colon || !eq || eq < colon) {
        fprintf(stderr, "modbus-sim: --set '%s': expected TABLE:ADDR=VALUE\n", arg);
        return -1;
    }
    *colon = *eq = '\0';
    return set_value(sim, arg, parse_num(colon + 1, 65535), parse_num(eq + 1, 65535));
}

/* Reads the table sizes and address options; 0 or -1. */
static int parse_sizes(sim_t *sim, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        long v = i + 1 < argc ? parse_num(argv[i + 1], 65536) : -1;
        int *dst = !strcmp(o, "--port") ? &sim->port : !strcmp(o, "--coils") ? &sim->ncoils
                 : !strcmp(o, "--discrete") ? &sim->ndi : !strcmp(o, "--holding") ? &sim->nhr
                 : !strcmp(o, "--input") ? &sim->nir : !strcmp(o, "--rtu") ? &sim->rtu_slave : NULL;
        if (dst && (v < 0 || (dst == &sim->port && v > 65535) || (dst == &sim->rtu_slave && v > 247)))
            return fprintf(stderr, "modbus-sim: %s needs a number\n", o), -1;
        if (dst)
            *dst = (int)v;
        else if (!strcmp(o, "--bind") && i + 1 < argc)
            sim->bind_addr = argv[i + 1];
        else if (strcmp(o, "--set") && strcmp(o, "--log"))
            return fprintf(stderr, "modbus-sim: unknown option '%s'\n", o), -1;
        i++;
    }
    return 0;
}

/* Applies --set and --log (after the tables exist); 0 or -1. */
static int parse_values(sim_t *sim, int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--set") && set_option(sim, argv[i + 1]))
            return -1;
        if (!strcmp(argv[i], "--log") && !(sim->log = fopen(argv[i + 1], "w")))
            return fprintf(stderr, "modbus-sim: %s: %s\n", argv[i + 1], strerror(errno)), -1;
    }
    return argc % 2 == 0 ? (usage(), -1) : 0;
}

/* Logs the elements a write request changed ("write TABLE ADDR VALUE" per element). */
static void log_write(sim_t *sim, modbus_t *ctx, const uint8_t *q)
{
    int hl = modbus_get_header_length(ctx);
    int fn = q[hl], addr = q[hl + 1] << 8 | q[hl + 2];
    int n = (fn == 15 || fn == 16) ? (q[hl + 3] << 8 | q[hl + 4]) : 1;
    if (!sim->log || (fn != 5 && fn != 6 && fn != 15 && fn != 16))
        return;
    int bits = fn == 5 || fn == 15;
    int size = bits ? sim->map->nb_bits : sim->map->nb_registers;
    for (int a = addr; a < addr + n && a < size; a++)
        fprintf(sim->log, "write %s %d %d\n", bits ? "coil" : "hr", a,
                bits ? sim->map->tab_bits[a] : sim->map->tab_registers[a]);
    fflush(sim->log);
}

/* Serves one request from client k; drops the client on EOF or error. */
static void serve_client(sim_t *sim, modbus_t *ctx, int k)
{
    uint8_t q[MODBUS_TCP_MAX_ADU_LENGTH];
    modbus_set_socket(ctx, sim->clients[k]);
    int rc = modbus_receive(ctx, q);
    if (rc > 0 && modbus_reply(ctx, q, rc, sim->map) >= 0) {
        log_write(sim, ctx, q);
        return;
    }
    if (rc == 0)
        return;
    close(sim->clients[k]);
    sim->clients[k] = sim->clients[--sim->nclients];
}

/* Serves one request arriving on the RTU pty; a broken frame is flushed. */
static void serve_rtu(sim_t *sim, modbus_t *ctx)
{
    uint8_t q[MODBUS_RTU_MAX_ADU_LENGTH];
    int rc = modbus_receive(ctx, q);
    if (rc > 0 && modbus_reply(ctx, q, rc, sim->map) >= 0)
        log_write(sim, ctx, q);
    else if (rc < 0)
        modbus_flush(ctx);
}

/* Runs one command line ("set TABLE ADDR VALUE" or "quit"); returns 1 on quit. */
static int run_command(sim_t *sim, const char *line)
{
    char table[16];
    long addr, value;
    if (!strncmp(line, "quit", 4))
        return 1;
    if (sscanf(line, "set %15s %ld %ld", table, &addr, &value) == 3 && addr >= 0 && value >= 0)
        set_value(sim, table, addr, value);
    else if (*line)
        fprintf(stderr, "modbus-sim: unknown command: %s\n", line);
    return 0;
}

/* Reads what stdin holds (raw, so select stays accurate) and runs each full line; 1 on quit. */
static int serve_stdin(sim_t *sim)
{
    static char buf[1024];
    static size_t used;
    ssize_t n = read(0, buf + used, sizeof(buf) - 1 - used);
    if (n <= 0) {
        sim->stdin_open = 0;
        return 0;
    }
    used += (size_t)n;
    buf[used] = '\0';
    char *line = buf, *nl;
    while ((nl = strchr(line, '\n'))) {
        *nl = '\0';
        if (run_command(sim, line))
            return 1;
        line = nl + 1;
    }
    used = strlen(line);
    memmove(buf, line, used + 1);
    if (used == sizeof(buf) - 1)
        used = 0;
    return 0;
}

/* Waits for activity and dispatches it; returns 1 to stop. */
static int poll_once(sim_t *sim, modbus_t *ctx, int lfd)
{
    fd_set rd;
    FD_ZERO(&rd);
    int maxfd = lfd > sim->rtu_fd ? lfd : sim->rtu_fd;
    FD_SET(maxfd, &rd);
    if (sim->stdin_open)
        FD_SET(0, &rd);
    for (int k = 0; k < sim->nclients; k++) {
        FD_SET(sim->clients[k], &rd);
        maxfd = sim->clients[k] > maxfd ? sim->clients[k] : maxfd;
    }
    if (select(maxfd + 1, &rd, NULL, NULL, NULL) < 0)
        return errno != EINTR;
    if (sim->stdin_open && FD_ISSET(0, &rd) && serve_stdin(sim))
        return 1;
    if (sim->rtu_fd >= 0 && FD_ISSET(sim->rtu_fd, &rd))
        serve_rtu(sim, ctx);
    for (int k = sim->nclients - 1; k >= 0; k--)
        if (FD_ISSET(sim->clients[k], &rd))
            serve_client(sim, ctx, k);
    int fd = lfd >= 0 && FD_ISSET(lfd, &rd) ? accept(lfd, NULL, NULL) : -1;
    if (fd >= 0 && sim->nclients < MAX_CLIENTS)
        sim->clients[sim->nclients++] = fd;
    else if (fd >= 0)
        close(fd);
    return 0;
}

/* Opens the listening socket and prints the port actually bound; the fd or -1. */
static int start_listening(sim_t *sim, modbus_t *ctx)
{
    int lfd = modbus_tcp_listen(ctx, 8);
    struct sockaddr_in sa;
    socklen_t len = sizeof(sa);
    if (lfd < 0 || getsockname(lfd, (struct sockaddr *)&sa, &len)) {
        fprintf(stderr, "modbus-sim: cannot listen on %s:%d: %s\n", sim->bind_addr, sim->port,
                modbus_strerror(errno));
        return -1;
    }
    printf("port %d\n", ntohs(sa.sin_port));
    fflush(stdout);
    return lfd;
}

/* Opens a pty for the RTU device and prints its path; the RTU context or NULL. */
static modbus_t *start_rtu(sim_t *sim)
{
    struct termios tio;
    int fd = posix_openpt(O_RDWR | O_NOCTTY);
    const char *path = (fd >= 0 && grantpt(fd) == 0 && unlockpt(fd) == 0) ? ptsname(fd) : NULL;
    sim->pty_keep_fd = path ? open(path, O_RDWR | O_NOCTTY) : -1;
    if (sim->pty_keep_fd < 0 || tcgetattr(sim->pty_keep_fd, &tio)) {
        fprintf(stderr, "modbus-sim: cannot create a pty: %s\n", strerror(errno));
        return NULL;
    }
    cfmakeraw(&tio);
    tcsetattr(sim->pty_keep_fd, TCSANOW, &tio);
    modbus_t *ctx = modbus_new_rtu(path, 9600, 'N', 8, 1);
    if (!ctx || modbus_set_slave(ctx, sim->rtu_slave) || modbus_set_socket(ctx, fd))
        return NULL;
    sim->rtu_fd = fd;
    printf("pty %s\n", path);
    fflush(stdout);
    return ctx;
}

/* Parses options, builds the tables and serves until "quit" or a signal. */
int main(int argc, char **argv)
{
    sim_t sim = {"127.0.0.1", 0, 1000, 1000, 1000, 1000, NULL, NULL, {0}, 0, 1, -1, -1, -1};
    if (argc == 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")))
        return usage_to(stdout, 0);
    if (parse_sizes(&sim, argc, argv))
        return usage();
    sim.map = modbus_mapping_new(sim.ncoils, sim.ndi, sim.nhr, sim.nir);
    if (!sim.map || parse_values(&sim, argc, argv))
        return 1;
    modbus_t *ctx;
    int lfd = -1;
    if (sim.rtu_slave >= 0) {
        ctx = start_rtu(&sim);
    } else {
        ctx = modbus_new_tcp(sim.bind_addr, sim.port);
        lfd = ctx ? start_listening(&sim, ctx) : -1;
    }
    if (!ctx || (sim.rtu_slave < 0 && lfd < 0))
        return 1;
    while (!poll_once(&sim, ctx, lfd))
        ;
    modbus_free(ctx);
    modbus_mapping_free(sim.map);
    return 0;
}
