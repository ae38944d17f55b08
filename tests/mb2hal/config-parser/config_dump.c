/* config_dump.c: unit test driver: parses mb2hal configs and prints what the parser understood. */
#include <stdio.h>

#include "mb2hal_config.h"

/* Prints the link and addressing of one transaction. */
static void dump_tx(const mb_tx_cfg_t *t)
{
    const mb_link_cfg_t *l = &t->link;
    if (l->type == MB_LINK_TCP)
        printf("[%s] tcp %s:%d", t->section, l->tcp_ip, l->tcp_port);
    else
        printf("[%s] serial %s %d %d%c%d delay=%d", t->section, l->serial_port, l->serial_baud,
               l->serial_bits, l->serial_parity, l->serial_stop, l->serial_delay_ms);
    printf(" slave=%d %s first=%d n=%d tx=%s timeouts=%d/%d rate=%g debug=%d", t->slave_id,
           mb2hal_code_name(t->code), t->first_element, t->nelements, t->tx_name,
           t->resp_timeout_ms, t->byte_timeout_ms, t->max_update_rate, t->debug);
    for (int i = 0; t->pin_names && i < t->nelements; i++)
        printf("%s%s", i ? "," : " names=", t->pin_names[i]);
    printf("\n");
}

/* Loads every file named on the command line and prints the result. */
int main(int argc, char **argv)
{
    static mb2hal_cfg_t cfg;
    setvbuf(stdout, NULL, _IONBF, 0);
    for (int i = 1; i < argc; i++) {
        printf("== %s\n", argv[i]);
        if (mb2hal_config_load(&cfg, argv[i])) {
            printf("rejected\n");
            continue;
        }
        printf("init_debug=%d version=%d.%d module=%s slowdown=%g ntx=%d\n", cfg.init_debug,
               cfg.version / 10, cfg.version % 10, cfg.module_name, cfg.slowdown, cfg.ntx);
        for (int t = 0; t < cfg.ntx; t++)
            dump_tx(&cfg.tx[t]);
        mb2hal_config_free(&cfg);
    }
    return 0;
}
