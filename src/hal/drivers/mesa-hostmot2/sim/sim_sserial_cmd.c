/* sim_sserial_cmd.c: mesa-sim's Smart Serial commands: show a remote's process data, set its
   inputs, pull and replace its cable. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_card.h"

/* The remote of channel text, or NULL (with a message). */
static sim_remote_t *remote_arg(sim_card_t *c, const char *text)
{
    char *end;
    long ch = text ? strtol(text, &end, 10) : -1;
    if (!text || *end || ch < 0 || ch >= c->board->sserial_channels || !c->sserial.remote[ch].type) {
        sim_say("error: no Smart Serial remote on channel '%s'", text ? text : "");
        return NULL;
    }
    return &c->sserial.remote[ch];
}

/* get sserial CH: state and every process-data value (outputs as the remote drives them). */
static void show(sim_card_t *c, sim_remote_t *r, const char *chan)
{
    char line[512];
    bool on = sim_remote_outputs_enabled(r, c->now_ns);
    int n = snprintf(line, sizeof(line), "sserial %s %s mode %d running %d outputs-enabled %d", chan,
                     r->type->name, r->mode, r->started, on);
    for (int i = 0; i < r->type->num_records && n < (int)sizeof(line); i++) {
        const sim_record_def_t *d = &r->type->records[i];
        if (!d->global && !(d->modes & (1u << r->mode)))
            continue;
        uint32_t v = r->value[i];
        if (d->global) {
            uint8_t lo = r->mem[r->rec_addr[i] + SSLBP_PD_ADDR], hi = r->mem[r->rec_addr[i] + SSLBP_PD_ADDR + 1];
            v = sim_remote_read32(r, (uint32_t)(lo | hi << 8));
            if (d->bits < 32)
                v &= (1u << d->bits) - 1;
        } else if (d->dir == SSLBP_DIR_OUT && !on) {
            v = 0;
        }
        n += snprintf(line + n, sizeof(line) - n, d->data_type == SSLBP_TYPE_BITS ? " %s 0x%x" : " %s %u",
                      d->name, v);
    }
    sim_say("%s", line);
}

/* set sserial CH NAME VALUE: an input record's raw value, or one bit (NAME-NN). */
static void set_input(sim_remote_t *r, const char *name, const char *value)
{
    int bit, i = sim_remote_find(r, name, &bit);
    if (i < 0 || r->type->records[i].dir == SSLBP_DIR_OUT || r->type->records[i].global) {
        sim_say("error: '%s' is not an input of the %s", name, r->type->name);
        return;
    }
    uint32_t v = (uint32_t)strtoul(value, NULL, 0);
    if (bit >= 0)
        r->value[i] = v ? r->value[i] | 1u << bit : r->value[i] & ~(1u << bit);
    else
        r->value[i] = v;
    sim_say("ok");
}

/* get sserial CH | set sserial CH NAME VALUE | sserial-unplug CH | sserial-plug CH |
   sserial-status CH N (status byte: 2 = field power lost) | sserial-busy N (the next N do-its
   stay unfinished). */
int sim_sserial_command(sim_card_t *c, int argc, char **argv)
{
    if (!strcmp(argv[0], "sserial-status")) {
        sim_remote_t *st = remote_arg(c, argc > 1 ? argv[1] : NULL);
        if (st) {
            st->status = (uint8_t)strtoul(argc > 2 ? argv[2] : "0", NULL, 0);
            sim_say("ok");
        }
        return 0;
    }
    if (!strcmp(argv[0], "sserial-busy")) {
        c->sserial.busy_doits = argc > 1 ? atoi(argv[1]) : 1;
        sim_say("ok");
        return 0;
    }
    bool is_get = !strcmp(argv[0], "get"), is_set = !strcmp(argv[0], "set");
    sim_remote_t *r = remote_arg(c, argc > (is_get || is_set ? 2 : 1) ? argv[is_get || is_set ? 2 : 1] : NULL);
    if (!r)
        return 0;
    if (is_get) {
        show(c, r, argv[2]);
    } else if (is_set) {
        if (argc < 5)
            sim_say("error: set sserial CH NAME VALUE");
        else
            set_input(r, argv[3], argv[4]);
    } else {
        r->unplugged = !strcmp(argv[0], "sserial-unplug");
        sim_say("ok");
    }
    return 0;
}
