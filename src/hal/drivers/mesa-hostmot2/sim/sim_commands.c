/* sim_commands.c: mesa-sim's control commands (stdin): inspect outputs, set inputs, inject faults. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_card.h"

#define MAX_ARGS 5

typedef int (*cmd_fn_t)(sim_card_t *c, int argc, char **argv);

/* Parse an index argument in 0..limit-1; -1 (with a message) otherwise. */
static int index_arg(const char *text, int limit, const char *what)
{
    char *end;
    long v = text ? strtol(text, &end, 0) : -1;
    if (!text || *end || v < 0 || v >= limit) {
        sim_say("error: %s index '%s' is not 0..%d", what, text ? text : "", limit - 1);
        return -1;
    }
    return (int)v;
}

/* get io N: the electrical level of IO N. */
static int cmd_get_io(sim_card_t *c, int argc, char **argv)
{
    int io = index_arg(argc > 2 ? argv[2] : NULL, c->board->ports * c->board->port_width, "io");
    if (io >= 0)
        sim_say("io %d %d", io, sim_io_level(c, io));
    return 0;
}

/* get stepgen N: rate register, step position, steps that reached the pin. */
static int cmd_get_stepgen(sim_card_t *c, int argc, char **argv)
{
    int s = index_arg(argc > 2 ? argv[2] : NULL, c->board->stepgens, "stepgen");
    if (s >= 0)
        sim_say("stepgen %d rate %d steps %lld emitted %lld", s, (int32_t)c->stepgen[s].rate,
                (long long)(c->stepgen[s].acc >> 32), (long long)c->stepgen[s].emitted_steps);
    return 0;
}

/* get encoder N: the count its inputs have produced. */
static int cmd_get_encoder(sim_card_t *c, int argc, char **argv)
{
    int e = index_arg(argc > 2 ? argv[2] : NULL, c->board->encoders, "encoder");
    if (e >= 0)
        sim_say("encoder %d count %lld", e, (long long)floor(c->encoder[e].position));
    return 0;
}

/* get pwm N: duty, resolution, frequency and enable as the card would output them. */
static int cmd_get_pwm(sim_card_t *c, int argc, char **argv)
{
    int p = index_arg(argc > 2 ? argv[2] : NULL, c->board->pwmgens, "pwmgen");
    int bits;
    if (p < 0)
        return 0;
    double duty = sim_pwm_duty(c, p, &bits);
    bool pdm = ((c->pwmgen[p].mode >> 3) & 3) == 3;
    double freq = pdm ? c->board->clock_high * (double)c->pdm_dds / 65536.0
                      : c->board->clock_high * (double)c->pwm_dds / 65536.0 / (1u << bits);
    sim_say("pwm %d duty %.4f bits %d freq %.1f enable %d value 0x%08x mode 0x%02x", p, duty, bits,
            freq, (c->pwm_enable >> p) & 1, c->pwmgen[p].value, c->pwmgen[p].mode);
    return 0;
}

/* get reg ADDR / watchdog / led. */
static int cmd_get(sim_card_t *c, int argc, char **argv)
{
    const char *what = argc > 1 ? argv[1] : "";
    if (!strcmp(what, "io")) return cmd_get_io(c, argc, argv);
    if (!strcmp(what, "stepgen")) return cmd_get_stepgen(c, argc, argv);
    if (!strcmp(what, "encoder")) return cmd_get_encoder(c, argc, argv);
    if (!strcmp(what, "pwm")) return cmd_get_pwm(c, argc, argv);
    if (!strcmp(what, "sserial")) return sim_sserial_command(c, argc, argv);
    if (!strcmp(what, "watchdog")) {
        sim_say("watchdog bitten %d timer 0x%08x", c->wd_bitten, c->wd_timer);
    } else if (!strcmp(what, "led")) {
        sim_say("led 0x%08x", c->led);
    } else if (!strcmp(what, "reg") && argc > 2) {
        uint16_t addr = (uint16_t)strtoul(argv[2], NULL, 0);
        sim_say("reg 0x%04x 0x%08x", addr, sim_reg_read(c, addr));
    } else {
        sim_say("error: get what? (io N, stepgen N, encoder N, pwm N, sserial CH, reg ADDR, watchdog, led)");
    }
    return 0;
}

/* set in N L (outside level of an IO) / set encoder N COUNTS. */
static int cmd_set(sim_card_t *c, int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "sserial")) {
        sim_sserial_command(c, argc, argv);
    } else if (argc == 4 && !strcmp(argv[1], "in")) {
        int io = index_arg(argv[2], c->board->ports * c->board->port_width, "io");
        if (io >= 0) {
            c->input_level[io] = atoi(argv[3]) != 0;
            sim_say("ok");
        }
    } else if (argc == 4 && !strcmp(argv[1], "encoder")) {
        int e = index_arg(argv[2], c->board->encoders, "encoder");
        if (e >= 0) {
            c->encoder[e].position = strtod(argv[3], NULL);
            sim_say("ok");
        }
    } else {
        sim_say("error: set in IO LEVEL | set encoder N COUNTS | set sserial CH NAME VALUE");
    }
    return 0;
}

/* Fault injection: drop/garble/stale N replies, delay US, pause, resume, bite, quad-error N. */
static int cmd_fault(sim_card_t *c, int argc, char **argv)
{
    long n = argc > 1 ? strtol(argv[1], NULL, 0) : 1;
    if (!strcmp(argv[0], "drop"))
        c->drop_replies = (int)n;
    else if (!strcmp(argv[0], "garble"))
        c->garble_replies = (int)n;
    else if (!strcmp(argv[0], "stale"))
        c->stale_replies = (int)n;
    else if (!strcmp(argv[0], "delay"))
        c->reply_delay_ns = n * 1000LL;
    else if (!strcmp(argv[0], "pause"))
        c->paused = true;
    else if (!strcmp(argv[0], "resume"))
        c->paused = false;
    else if (!strcmp(argv[0], "bite")) {
        c->wd_timer = 0;
        c->wd_deadline_ns = c->now_ns - 1;
        sim_advance(c, c->now_ns + 1);
        return 0;
    } else if (!strcmp(argv[0], "quad-error")) {
        int e = index_arg(argc > 1 ? argv[1] : NULL, c->board->encoders, "encoder");
        if (e < 0)
            return 0;
        c->encoder[e].quad_error = true;
    }
    sim_say("ok");
    return 0;
}

/* stats: datagrams in/out/dropped and register writes. */
static int cmd_stats(sim_card_t *c, int argc, char **argv)
{
    (void)argc; (void)argv;
    sim_say("stats rx %lu tx %lu dropped %lu writes %lu", c->rx_packets, c->tx_packets, c->dropped,
            c->writes);
    return 0;
}

/* quit: end the program. */
static int cmd_quit(sim_card_t *c, int argc, char **argv)
{
    (void)c; (void)argc; (void)argv;
    return 1;
}

static const struct {
    const char *name;
    cmd_fn_t fn;
} commands[] = {
    {"get", cmd_get}, {"set", cmd_set}, {"drop", cmd_fault}, {"garble", cmd_fault},
    {"stale", cmd_fault}, {"delay", cmd_fault}, {"pause", cmd_fault}, {"resume", cmd_fault},
    {"bite", cmd_fault}, {"quad-error", cmd_fault}, {"stats", cmd_stats}, {"quit", cmd_quit},
    {"sserial-unplug", sim_sserial_command}, {"sserial-plug", sim_sserial_command},
    {"sserial-busy", sim_sserial_command}, {"sserial-status", sim_sserial_command},
};

/* Run one command line; 1 = quit. */
int sim_command(sim_card_t *c, char *line)
{
    char *argv[MAX_ARGS + 1];
    int argc = 0;
    for (char *tok = strtok(line, " \t\r\n"); tok && argc < MAX_ARGS; tok = strtok(NULL, " \t\r\n"))
        argv[argc++] = tok;
    argv[argc] = NULL;
    if (argc == 0)
        return 0;
    for (size_t i = 0; i < sizeof(commands) / sizeof(commands[0]); i++)
        if (!strcmp(argv[0], commands[i].name))
            return commands[i].fn(c, argc, argv);
    sim_say("error: unknown command '%s'", argv[0]);
    return 0;
}
