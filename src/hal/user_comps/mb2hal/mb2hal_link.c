/* mb2hal_link.c: Modbus connections of mb2hal (TCP or RTU), shared by equal links, with reconnect backoff. */
#include "mb2hal.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define RECONNECT_DELAY_S 1.0

/* Monotonic clock in seconds. */
double mb_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Sleeps seconds (returns early on a signal). */
void mb_sleep(double seconds)
{
    if (seconds <= 0)
        return;
    struct timespec ts = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    nanosleep(&ts, NULL);
}

/* Non-zero when two link settings name the same connection. */
static int same_link(const mb_link_cfg_t *a, const mb_link_cfg_t *b)
{
    if (a->type != b->type)
        return 0;
    if (a->type == MB_LINK_TCP)
        return strcmp(a->tcp_ip, b->tcp_ip) == 0 && a->tcp_port == b->tcp_port;
    return strcmp(a->serial_port, b->serial_port) == 0;
}

/* Index of the link matching cfg, adding it when new. */
int mb_link_find(mb_link_t *links, int *nlinks, const mb_link_cfg_t *cfg)
{
    for (int i = 0; i < *nlinks; i++)
        if (same_link(&links[i].cfg, cfg))
            return i;
    memset(&links[*nlinks], 0, sizeof(mb_link_t));
    links[*nlinks].cfg = *cfg;
    return (*nlinks)++;
}

/* Human-readable name of a link for messages. */
static void link_name(const mb_link_cfg_t *c, char *buf, size_t size)
{
    if (c->type == MB_LINK_TCP)
        snprintf(buf, size, "%s:%d", c->tcp_ip, c->tcp_port);
    else
        snprintf(buf, size, "%s", c->serial_port);
}

/* Creates a libmodbus context for the link settings. */
static modbus_t *new_context(const mb_link_cfg_t *c)
{
    if (c->type == MB_LINK_TCP)
        return modbus_new_tcp(c->tcp_ip, c->tcp_port);
    return modbus_new_rtu(c->serial_port, c->serial_baud, c->serial_parity, c->serial_bits,
                          c->serial_stop);
}

/* Applies the timeouts of tx (connect uses the response timeout). */
static void set_timeouts(modbus_t *ctx, const mb_tx_cfg_t *tx)
{
    modbus_set_response_timeout(ctx, (uint32_t)(tx->resp_timeout_ms / 1000),
                                (uint32_t)(tx->resp_timeout_ms % 1000) * 1000);
    modbus_set_byte_timeout(ctx, (uint32_t)(tx->byte_timeout_ms / 1000),
                            (uint32_t)(tx->byte_timeout_ms % 1000) * 1000);
}

/* Connects a fresh context; 0 or -1 with the backoff armed. */
static int link_connect(mb_link_t *link, const mb_tx_cfg_t *tx)
{
    char name[300];
    link_name(&link->cfg, name, sizeof(name));
    link->ctx = new_context(&link->cfg);
    if (link->ctx) {
        set_timeouts(link->ctx, tx);
        if (modbus_connect(link->ctx) == 0) {
            if (tx->debug >= 2)
                fprintf(stderr, "mb2hal: [%s] connected to %s\n", tx->section, name);
            link->down = 0;
            return 0;
        }
    }
    if (tx->debug >= 3 || (tx->debug >= 1 && !link->down))
        fprintf(stderr, "mb2hal: [%s] cannot connect to %s: %s\n", tx->section, name,
                modbus_strerror(errno));
    if (link->ctx)
        modbus_free(link->ctx);
    link->ctx = NULL;
    link->down = 1;
    link->retry_at = mb_now() + RECONNECT_DELAY_S;
    return -1;
}

/* Makes sure link is connected and set up for tx; 0, 1 while a reconnect is not due, or -1. */
int mb_link_open(mb_link_t *link, const mb_tx_cfg_t *tx)
{
    if (!link->ctx && mb_now() < link->retry_at)
        return 1;
    if (!link->ctx && link_connect(link, tx))
        return -1;
    set_timeouts(link->ctx, tx);
    if (modbus_set_slave(link->ctx, tx->slave_id)) {
        if (tx->debug >= 1)
            fprintf(stderr, "mb2hal: [%s] slave id %d refused: %s\n", tx->section, tx->slave_id,
                    modbus_strerror(errno));
        return -1;
    }
    if (link->cfg.type == MB_LINK_SERIAL && link->cfg.serial_delay_ms)
        mb_sleep(link->last_use + link->cfg.serial_delay_ms / 1000.0 - mb_now());
    return 0;
}

/* Drops the connection; the next open reconnects. */
void mb_link_close(mb_link_t *link)
{
    if (!link->ctx)
        return;
    modbus_close(link->ctx);
    modbus_free(link->ctx);
    link->ctx = NULL;
}
