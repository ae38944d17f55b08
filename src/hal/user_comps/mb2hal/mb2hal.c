/* mb2hal.c: user-space HAL component running Modbus transactions from an INI config (LinuxCNC mb2hal):
 * one thread per link cycles through that link's transactions; the main thread waits for a stop signal. */
#include "mb2hal.h"

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mb2hal_log.h"

#define STOP_POLL_S 0.05

/* One link and the thread that runs its transactions. */
typedef struct {
    mb_link_t *link;
    mb_tx_t *txs;           /* every transaction; the thread runs those on its link */
    int ntx;
    double slowdown;
    volatile int *stop;     /* set by the main thread when a stop signal arrived */
    pthread_t thread;
} mb_worker_t;

/* Path from the single "config=FILE" argument, or NULL after printing usage (help: *help set). */
static const char *config_arg(int argc, char **argv, int *help)
{
    *help = argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0);
    if (*help) {
        printf("Usage: mb2hal config=FILE.ini\n"
               "Modbus master as a HAL user component: reads and writes the coils and registers\n"
               "of Modbus TCP and RTU devices as FILE.ini's [TRANSACTION_NN] sections describe\n"
               "and shows them as pins named after [MB2HAL_INIT]HAL_MODULE_NAME (default mb2hal).\n"
               "Runs until SIGTERM, SIGINT or SIGHUP (halcmd unloadusr).\n");
        return NULL;
    }
    if (argc == 2 && strncmp(argv[1], "config=", 7) == 0 && argv[1][7])
        return argv[1] + 7;
    fprintf(stderr, "mb2hal: usage: mb2hal config=FILE.ini\n");
    return NULL;
}

/* Logs a link as LinuxCNC's init_mb_links does. */
static void log_link(int d, int n, const mb_link_cfg_t *l)
{
    if (l->type == MB_LINK_SERIAL)
        mb_log(d, MB_LOG_DEBUG, "init_mb_links",
               "LINK %d (RTU) link_type[%d] device[%s] baud[%d] data[%d] parity[%c] stop[%d] fd[-1]", n,
               MB_LOG_LINK_RTU, l->serial_port, l->serial_baud, l->serial_bits, l->serial_parity,
               l->serial_stop);
    else
        mb_log(d, MB_LOG_DEBUG, "init_mb_links", "LINK %d (TCP) link_type[%d] IP[%s] port[%d] fd[-1]", n,
               MB_LOG_LINK_TCP, l->tcp_ip, l->tcp_port);
}

/* Binds every transaction to its (shared) link; returns the number of links. */
static int bind_links(const mb2hal_cfg_t *cfg, mb_tx_t *txs, mb_link_t *links)
{
    int nlinks = 0, d = cfg->init_debug;
    for (int i = 0; i < cfg->ntx; i++) {
        int before = nlinks, n = mb_link_find(links, &nlinks, &cfg->tx[i].link);
        if (nlinks > before)
            log_link(d, n, &cfg->tx[i].link);
        txs[i].cfg = &cfg->tx[i];
        txs[i].link = &links[n];
    }
    mb_log(d, MB_LOG_OK, "main", "init_gbl.mb_link done OK");
    for (int i = 0; i < cfg->ntx; i++) {
        double rate = cfg->tx[i].max_update_rate;
        mb_log(d, MB_LOG_DEBUG, "init_mb_tx",
               "MB_TX %d lk_n[%d] tx_n[%d] cfg_dbg[%d] lk_dbg[0] t_inc[%0.3f] nxt_t[%0.3f]", i,
               (int)(txs[i].link - links), i, cfg->tx[i].debug, rate > 0 ? 1.0 / rate : 0.0, 0.0);
    }
    mb_log(d, MB_LOG_OK, "main", "init_gbl.mb_tx done OK");
    return nlinks;
}

/* Creates the pins of every transaction; 0 or -1. */
static int create_pins(const mb2hal_cfg_t *cfg, mb_tx_t *txs, int comp_id)
{
    for (int i = 0; i < cfg->ntx; i++) {
        int rc = mb_pins_create(&txs[i], comp_id, cfg->module_name, i, cfg->init_debug);
        if (rc) {
            fprintf(stderr, "mb2hal: [%s] cannot create pins of '%s.%s': error %d\n",
                    cfg->tx[i].section, cfg->module_name, cfg->tx[i].tx_name, rc);
            return -1;
        }
    }
    mb_log(cfg->init_debug, MB_LOG_OK, "main", "HAL components created OK");
    return 0;
}

/* Sleeps seconds in short slices, returning early once a stop is requested. */
static void sleep_unless_stopped(double seconds, volatile int *stop)
{
    while (seconds > 0 && !*stop) {
        double slice = seconds < STOP_POLL_S ? seconds : STOP_POLL_S;
        mb_sleep(slice);
        seconds -= slice;
    }
}

/* Runs tx when its MAX_UPDATE_RATE allows; returns 1 when it talked to the device. */
static int run_due(mb_tx_t *tx, const mb_worker_t *w)
{
    double now = mb_now();
    if (now < tx->next_at)
        return 0;
    if (tx->cfg->max_update_rate > 0)
        tx->next_at = now + 1.0 / tx->cfg->max_update_rate;
    if (mb_tx_run(tx) > 0)
        return 0;
    sleep_unless_stopped(w->slowdown, w->stop);
    return 1;
}

/* Link thread: cycles through the transactions of its link until stopped. */
static void *link_loop(void *arg)
{
    mb_worker_t *w = arg;
    while (!*w->stop) {
        int ran = 0;
        for (int i = 0; i < w->ntx && !*w->stop; i++)
            if (w->txs[i].link == w->link)
                ran += run_due(&w->txs[i], w);
        if (!ran)
            mb_sleep(0.001);
    }
    return NULL;
}

/* Starts one thread per link; returns how many started. */
static int start_workers(const mb2hal_cfg_t *cfg, mb_worker_t *workers, mb_link_t *links, int nlinks,
                         mb_tx_t *txs, volatile int *stop)
{
    for (int i = 0; i < nlinks; i++) {
        workers[i] = (mb_worker_t){&links[i], txs, cfg->ntx, cfg->slowdown, stop, 0};
        if (pthread_create(&workers[i].thread, NULL, link_loop, &workers[i])) {
            fprintf(stderr, "mb2hal: cannot start the thread of link %d\n", i);
            return i;
        }
        mb_log(cfg->init_debug, MB_LOG_OK, "main", "Link thread loop and logic %d created OK", i);
    }
    return nlinks;
}

/* Blocks until SIGTERM, SIGINT or SIGHUP and returns it (the signals stay blocked in every thread). */
static int wait_for_stop_signal(const sigset_t *set)
{
    int sig = 0;
    while (sigwait(set, &sig) != 0)
        ;
    return sig;
}

/* Starts the links, reports ready (after the start-up log, so it comes first), runs until a stop signal,
 * then stops the threads. */
static void run(const mb2hal_cfg_t *cfg, mb_tx_t *txs, mb_link_t *links, int nlinks, const sigset_t *set,
                int comp_id)
{
    static mb_worker_t workers[MB2HAL_MAX_TX];
    static volatile int stop;
    int started = start_workers(cfg, workers, links, nlinks, txs, &stop);
    int sig = 0;
    if (started == nlinks) {
        mb_log(cfg->init_debug, MB_LOG_OK, "main", "mb2hal is running");
        hal_ready(comp_id);
        sig = wait_for_stop_signal(set);
    }
    stop = 1;
    for (int i = 0; i < started; i++)
        pthread_join(workers[i].thread, NULL);
    if (sig)
        mb_log(cfg->init_debug, MB_LOG_DEBUG, "quit_signal", "signal [%d] received", sig);
}

/* Loads the config, creates the component and runs until SIGTERM/SIGINT/SIGHUP. */
int main(int argc, char **argv)
{
    static mb2hal_cfg_t cfg;
    static mb_tx_t txs[MB2HAL_MAX_TX];
    static mb_link_t links[MB2HAL_MAX_TX];
    sigset_t set;
    int help;
    const char *path = config_arg(argc, argv, &help);
    if (!path || mb2hal_config_load(&cfg, path))
        return help ? 0 : 1;
    int d = cfg.init_debug;
    mb_log(d, MB_LOG_OK, "main", "parse_ini_file done OK");
    sigemptyset(&set);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &set, NULL);
    int nlinks = bind_links(&cfg, txs, links);
    int comp_id = hal_init(cfg.module_name);
    if (comp_id < 0) {
        fprintf(stderr, "mb2hal: hal_init(%s) failed: error %d\n", cfg.module_name, comp_id);
        mb2hal_config_free(&cfg);
        return 1;
    }
    int rc = create_pins(&cfg, txs, comp_id);
    if (rc == 0)
        run(&cfg, txs, links, nlinks, &set, comp_id);
    mb_log(d, MB_LOG_DEBUG, "quit_cleanup", "started");
    for (int i = 0; i < nlinks; i++)
        mb_link_close(&links[i]);
    mb_log(d, MB_LOG_DEBUG, "quit_cleanup", "unloading HAL module [%d] ret[%d]", comp_id, hal_exit(comp_id));
    mb_log(d, MB_LOG_DEBUG, "quit_cleanup", "done OK");
    mb_log(d, MB_LOG_OK, "main", "going to exit!");
    mb2hal_config_free(&cfg);
    return rc ? 1 : 0;
}
