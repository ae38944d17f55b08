/* mb2hal.c: user-space HAL component running Modbus transactions from an INI config (LinuxCNC mb2hal). */
#include "mb2hal.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static volatile sig_atomic_t stop_requested;

/* SIGTERM/SIGINT handler: ends the main loop. */
static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

/* Installs the stop handlers (no SA_RESTART, so sleeps end early). */
static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
}

/* Path from the single "config=FILE" argument, or NULL after printing usage (help: *help set). */
static const char *config_arg(int argc, char **argv, int *help)
{
    *help = argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0);
    if (*help) {
        printf("Usage: mb2hal config=FILE.ini\n"
               "Modbus master as a HAL user component: reads and writes the coils and registers\n"
               "of Modbus TCP and RTU devices as FILE.ini's [TRANSACTION_NN] sections describe\n"
               "and shows them as pins named after [MB2HAL_INIT]HAL_MODULE_NAME (default mb2hal).\n"
               "Runs until SIGTERM or SIGINT (halcmd unloadusr).\n");
        return NULL;
    }
    if (argc == 2 && strncmp(argv[1], "config=", 7) == 0 && argv[1][7])
        return argv[1] + 7;
    fprintf(stderr, "mb2hal: usage: mb2hal config=FILE.ini\n");
    return NULL;
}

/* Binds transactions to shared links and creates their pins; 0 or -1. */
static int setup(const mb2hal_cfg_t *cfg, mb_tx_t *txs, mb_link_t *links, int comp_id)
{
    int nlinks = 0;
    for (int i = 0; i < cfg->ntx; i++) {
        txs[i].cfg = &cfg->tx[i];
        txs[i].link = &links[mb_link_find(links, &nlinks, &cfg->tx[i].link)];
        int rc = mb_pins_create(&txs[i], comp_id, cfg->module_name);
        if (rc) {
            fprintf(stderr, "mb2hal: [%s] cannot create pins of '%s.%s': error %d\n",
                    cfg->tx[i].section, cfg->module_name, cfg->tx[i].tx_name, rc);
            return -1;
        }
    }
    return 0;
}

/* Runs tx when its MAX_UPDATE_RATE allows; returns 1 when it talked to the device. */
static int run_due(mb_tx_t *tx, double slowdown)
{
    double now = mb_now();
    if (now < tx->next_at)
        return 0;
    if (tx->cfg->max_update_rate > 0)
        tx->next_at = now + 1.0 / tx->cfg->max_update_rate;
    if (mb_tx_run(tx) > 0)
        return 0;
    mb_sleep(slowdown);
    return 1;
}

/* Cycles through the transactions until a stop signal arrives. */
static void main_loop(const mb2hal_cfg_t *cfg, mb_tx_t *txs)
{
    while (!stop_requested) {
        int ran = 0;
        for (int i = 0; i < cfg->ntx && !stop_requested; i++)
            ran += run_due(&txs[i], cfg->slowdown);
        if (!ran)
            mb_sleep(0.001);
    }
}

/* Loads the config, creates the component and runs until SIGTERM/SIGINT. */
int main(int argc, char **argv)
{
    static mb2hal_cfg_t cfg;
    static mb_tx_t txs[MB2HAL_MAX_TX];
    static mb_link_t links[MB2HAL_MAX_TX];
    int help;
    const char *path = config_arg(argc, argv, &help);
    if (!path || mb2hal_config_load(&cfg, path))
        return help ? 0 : 1;
    install_signals();
    int comp_id = hal_init(cfg.module_name);
    if (comp_id < 0) {
        fprintf(stderr, "mb2hal: hal_init(%s) failed: error %d\n", cfg.module_name, comp_id);
        mb2hal_config_free(&cfg);
        return 1;
    }
    int rc = setup(&cfg, txs, links, comp_id);
    if (rc == 0) {
        hal_ready(comp_id);
        if (cfg.init_debug >= 2)
            fprintf(stderr, "mb2hal: %s ready, %d transactions\n", cfg.module_name, cfg.ntx);
        main_loop(&cfg, txs);
    }
    for (int i = 0; i < MB2HAL_MAX_TX; i++)
        mb_link_close(&links[i]);
    hal_exit(comp_id);
    mb2hal_config_free(&cfg);
    return rc ? 1 : 0;
}
