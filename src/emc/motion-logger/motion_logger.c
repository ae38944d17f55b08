/* motion_logger.c: motion-logger, LinuxCNC's user-space stand-in for motmod: owns the command ring and logs every command. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "hal.h"
#include "motion_client.h"
#include "ml_format.h"
#include "ml_state.h"

#define POLL_NS 1000000L        /* one "servo cycle" of the stand-in */

static volatile sig_atomic_t stop_requested;

/* SIGTERM/SIGINT end the loop. */
static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

/* Keep an unknown command in the echo's rejection history (as motmod does). */
static void reject(emcmot_status_t *st, const emcmot_command_t *cmd)
{
    emcmot_reject_t *r = &st->echo.reject[st->echo.reject_next % EMCMOT_REJECT_HISTORY];

    r->serial = cmd->serial;
    r->command = cmd->command;
    r->result = EMCMOT_COMMAND_UNKNOWN_COMMAND;
    r->reported = 0;
    snprintf(r->reason, sizeof r->reason, "unrecognized command %d", cmd->command);
    st->echo.reject_next = (st->echo.reject_next + 1) % EMCMOT_REJECT_HISTORY;
    st->echo.rejected++;
}

/* Log, apply and echo every queued command. */
static void drain(emcmot_shm_t *shm, FILE *log, emcmot_status_t *st)
{
    emcmot_command_t cmd;

    while (emcmot_ring_peek(shm, &cmd)) {
        emcmot_ring_pop(shm);
        ml_format(log, &cmd);
        fflush(log);
        ml_state_apply(st, &cmd);
        st->echo.serial = cmd.serial;
        st->echo.command = cmd.command;
        st->echo.result = emcmot_command_name(cmd.command) ? EMCMOT_COMMAND_OK
                                                           : EMCMOT_COMMAND_UNKNOWN_COMMAND;
        st->echo.handled++;
        if (st->echo.result != EMCMOT_COMMAND_OK)
            reject(st, &cmd);
    }
}

/* Serve the ring until told to stop. */
static void serve(emcmot_client_t *client, FILE *log)
{
    static emcmot_status_t st;
    emcmot_shm_t *shm = emcmot_client_shm(client);
    struct timespec ts = { 0, POLL_NS };

    ml_state_init(&st);
    emcmot_status_publish(shm, &st);
    while (!stop_requested) {
        drain(shm, log, &st);
        st.heartbeat++;
        emcmot_status_publish(shm, &st);
        nanosleep(&ts, NULL);
    }
}

/* The HAL component loadusr -W waits for. */
static int hal_start(void)
{
    int id = hal_init("motion-logger");

    if (id < 0) {
        fprintf(stderr, "motion-logger: hal_init failed (%d)\n", id);
        return id;
    }
    hal_ready(id);
    return id;
}

int main(int argc, char **argv)
{
    emcmot_client_t *client;
    FILE *log = stdout;
    char why[256];
    int key = EMCMOT_SHM_DEFAULT_KEY, opt, comp_id;

    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        printf("%s\n", "Usage: motion-logger [-k SHMEM_KEY] [LOGFILE]");
        return 0;
    }
    while ((opt = getopt(argc, argv, "k:")) != -1) {
        if (opt != 'k') {
            fprintf(stderr, "usage: motion-logger [-k SHMEM_KEY] [LOGFILE]\n");
            return 2;
        }
        key = atoi(optarg);
    }
    if (optind < argc && !(log = fopen(argv[optind], "w"))) {
        fprintf(stderr, "motion-logger: %s: %s\n", argv[optind], strerror(errno));
        return 1;
    }
    if (emcmot_create(key, "motion-logger", &client, why, sizeof why) < 0) {
        fprintf(stderr, "motion-logger: %s\n", why);
        return 1;
    }
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    comp_id = hal_start();
    if (comp_id >= 0)
        serve(client, log);
    emcmot_detach(client);
    if (comp_id >= 0)
        hal_exit(comp_id);
    if (log != stdout)
        fclose(log);
    return comp_id < 0 ? 1 : 0;
}
