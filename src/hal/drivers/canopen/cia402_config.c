/* cia402_config.c: read the cia402 configuration file and check every value, naming file and line. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cia402_config.h"
#include "cia402_sdo_line.h"

#define CFG_MSG_LEN 600
#define CFG_TEXT_LEN 256
#define GLOBAL_SECTION "CIA402"
#define DRIVE_PREFIX "CIA402_DRIVE_"

/* Working state of one load. */
typedef struct {
    co_ini_t ini;
    cia402_cfg_t *cfg;
    co_report_fn report;
    void *ctx;
    int errors;
} cfg_ctx_t;

/* Report "path:line: text" and count it. */
static void error_at(cfg_ctx_t *c, int line, const char *fmt, ...)
{
    char text[CFG_TEXT_LEN], msg[CFG_MSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof(text), fmt, ap);
    va_end(ap);
    if (line > 0)
        snprintf(msg, sizeof(msg), "%.255s:%d: %.255s", c->cfg->path, line, text);
    else
        snprintf(msg, sizeof(msg), "%.255s: %.255s", c->cfg->path, text);
    c->report(c->ctx, msg);
    c->errors++;
}

/* Parse a whole integer: decimal, or hexadecimal with 0x; 0 on success. */
static int parse_long(const char *s, long long *out)
{
    char *end;
    int base = (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) ||
               (s[0] == '-' && s[1] == '0' && (s[2] == 'x' || s[2] == 'X')) ? 16 : 10;
    errno = 0;
    *out = strtoll(s, &end, base);
    return (*s && !*end && errno == 0) ? 0 : -1;
}

/* An integer key within [min, max]; 0 on success, else reported. */
static int int_value(cfg_ctx_t *c, const co_ini_entry_t *e, long long min, long long max, int *out)
{
    long long v;
    if (parse_long(e->value, &v) != 0 || v < min || v > max) {
        error_at(c, e->line, "%s must be an integer from %lld to %lld, not '%s'", e->key, min, max, e->value);
        return -1;
    }
    *out = (int)v;
    return 0;
}

/* NODE_ID = 1..127 */
static void set_node_id(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    if (int_value(c, e, 1, CO_MAX_NODE, &d->node_id) == 0)
        d->node_line = e->line;
}

/* INTERFACE = a SocketCAN interface name */
static void set_interface(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    const char *v = e->value;
    int ok = *v && strlen(v) < CIA402_IFNAME_LEN;
    for (const char *p = v; ok && *p; p++)
        ok = isgraph((unsigned char)*p) && *p != '/' && *p != ':';
    if (!ok) {
        error_at(c, e->line, "INTERFACE must be a network interface name (1 to 15 characters), not '%s'", v);
        return;
    }
    snprintf(d->interface, sizeof(d->interface), "%s", v);
}

/* POSITION_SCALE = drive counts per machine unit (not zero; negative reverses) */
static void set_scale(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    char *end;
    double v = strtod(e->value, &end);
    if (!*e->value || *end || !isfinite(v) || v == 0.0) {
        error_at(c, e->line, "POSITION_SCALE must be a non-zero number (drive counts per machine unit), not '%s'",
                 e->value);
        return;
    }
    d->position_scale = v;
}

/* HEARTBEAT_MS = 1..65535 */
static void set_heartbeat(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    if (int_value(c, e, 1, 65535, &d->heartbeat_ms) == 0)
        d->heartbeat_line = e->line;
}

/* HEARTBEAT_TIMEOUT_MS = 1..600000 */
static void set_heartbeat_timeout(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    int_value(c, e, 1, 600000, &d->heartbeat_timeout_ms);
}

/* PDO_TIMEOUT_MS = 1..60000 */
static void set_pdo_timeout(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    int_value(c, e, 1, 60000, &d->pdo_timeout_ms);
}

/* SDO_TIMEOUT_MS = 1..60000 */
static void set_sdo_timeout(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    int_value(c, e, 1, 60000, &d->sdo_timeout_ms);
}

/* ENABLE_TIMEOUT_MS = 1..600000 */
static void set_enable_timeout(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    int_value(c, e, 1, 600000, &d->enable_timeout_ms);
}

/* VELOCITY_FEEDBACK = 0 or 1 */
static void set_velocity(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    if (int_value(c, e, 0, 1, &d->velocity_feedback) == 0)
        d->velocity_line = e->line;
}

/* SYNC_PERIOD_OBJECTS = 0 or 1 */
static void set_sync_objects(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    if (int_value(c, e, 0, 1, &d->sync_period_objects) == 0)
        d->sync_line = e->line;
}

/* SYNC_COB_ID = 0x001..0x7FF ([CIA402] only) */
static void set_sync_id(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    int v;
    (void)d;
    if (int_value(c, e, 1, 0x7FF, &v) == 0)
        c->cfg->sync_cob_id = (uint16_t)v;
}

static void cia402_cfg_add_sdo(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e);

#define IN_GLOBAL 1u
#define IN_DRIVE 2u
#define REPEATABLE 4u

/* Every key: where it may appear and how it is read. */
static const struct {
    const char *key;
    unsigned where;
    void (*set)(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e);
} keys[] = {
    { "NODE_ID", IN_DRIVE, set_node_id },
    { "INTERFACE", IN_GLOBAL | IN_DRIVE, set_interface },
    { "POSITION_SCALE", IN_DRIVE, set_scale },
    { "HEARTBEAT_MS", IN_GLOBAL | IN_DRIVE, set_heartbeat },
    { "HEARTBEAT_TIMEOUT_MS", IN_GLOBAL | IN_DRIVE, set_heartbeat_timeout },
    { "PDO_TIMEOUT_MS", IN_GLOBAL | IN_DRIVE, set_pdo_timeout },
    { "SDO_TIMEOUT_MS", IN_GLOBAL | IN_DRIVE, set_sdo_timeout },
    { "ENABLE_TIMEOUT_MS", IN_GLOBAL | IN_DRIVE, set_enable_timeout },
    { "VELOCITY_FEEDBACK", IN_GLOBAL | IN_DRIVE, set_velocity },
    { "SYNC_PERIOD_OBJECTS", IN_GLOBAL | IN_DRIVE, set_sync_objects },
    { "SYNC_COB_ID", IN_GLOBAL, set_sync_id },
    { "SDO", IN_DRIVE | REPEATABLE, cia402_cfg_add_sdo },
};
#define KEY_COUNT (sizeof(keys) / sizeof(keys[0]))

/* Apply the entries of one section to d; where is IN_GLOBAL or IN_DRIVE. */
static void apply_section(cfg_ctx_t *c, const char *section, unsigned where, cia402_drive_cfg_t *d)
{
    int first_line[KEY_COUNT] = { 0 };
    for (int i = 0; i < c->ini.count; i++) {
        const co_ini_entry_t *e = &c->ini.entries[i];
        unsigned k = 0;
        if (strcmp(e->section, section) != 0)
            continue;
        while (k < KEY_COUNT && strcmp(keys[k].key, e->key) != 0)
            k++;
        if (k == KEY_COUNT || !(keys[k].where & where)) {
            error_at(c, e->line, "unknown key %s in [%s]", e->key, section);
        } else if (first_line[k] && !(keys[k].where & REPEATABLE)) {
            error_at(c, e->line, "%s is given twice in [%s] (first at line %d)", e->key, section, first_line[k]);
        } else {
            first_line[k] = e->line;
            keys[k].set(c, d, e);
        }
    }
}

/* The drive number of a [CIA402_DRIVE_n] section name, -1 for a malformed one, -2 for another section. */
static int drive_number(const char *name)
{
    const char *digits = name + strlen(DRIVE_PREFIX);
    long n;
    char *end;
    if (strncmp(name, DRIVE_PREFIX, strlen(DRIVE_PREFIX)) != 0)
        return -2;
    if (!isdigit((unsigned char)*digits) || (digits[0] == '0' && digits[1]))
        return -1;
    n = strtol(digits, &end, 10);
    return (*end || n >= CIA402_MAX_DRIVES) ? -1 : (int)n;
}

/* Check the section headers; fills line_of[n] for every drive section. */
static void scan_sections(cfg_ctx_t *c, int line_of[CIA402_MAX_DRIVES], int *global_line)
{
    for (int i = 0; i < c->ini.section_count; i++) {
        const co_ini_section_t *s = &c->ini.sections[i];
        int n = drive_number(s->name);
        if (n == -1)
            error_at(c, s->line, "[%s]: drive sections are [CIA402_DRIVE_0] to [CIA402_DRIVE_%d]", s->name,
                     CIA402_MAX_DRIVES - 1);
        int *slot = n >= 0 ? &line_of[n] : strcmp(s->name, GLOBAL_SECTION) == 0 ? global_line : NULL;
        if (!slot)
            continue;
        if (*slot)
            error_at(c, s->line, "[%s] appears twice (first at line %d)", s->name, *slot);
        else
            *slot = s->line;
    }
}

/* Defaults before [CIA402] is applied. */
static void set_defaults(cia402_drive_cfg_t *d)
{
    memset(d, 0, sizeof(*d));
    d->position_scale = 1.0;
    d->heartbeat_ms = 100;
    d->pdo_timeout_ms = 20;
    d->sdo_timeout_ms = 100;
    d->enable_timeout_ms = 1000;
    d->velocity_feedback = 1;
    d->sync_period_objects = 1;
}

/* Checks of one complete drive section. */
static void check_drive(cfg_ctx_t *c, cia402_drive_cfg_t *d)
{
    if (!d->node_id)
        error_at(c, d->section_line, "[CIA402_DRIVE_%d] has no NODE_ID", d->number);
    if (!d->interface[0])
        error_at(c, d->section_line, "[CIA402_DRIVE_%d] has no INTERFACE (and [CIA402] gives none)", d->number);
    if (!d->heartbeat_timeout_ms)
        d->heartbeat_timeout_ms = 3 * d->heartbeat_ms;
    else if (d->heartbeat_timeout_ms <= d->heartbeat_ms)
        error_at(c, d->section_line, "[CIA402_DRIVE_%d]: HEARTBEAT_TIMEOUT_MS (%d) must be longer than "
                 "HEARTBEAT_MS (%d)", d->number, d->heartbeat_timeout_ms, d->heartbeat_ms);
    for (int i = 0; i < d->sdo_count; i++) {
        const char *why = cia402_sdo_reserved(d->sdo[i].write.index, d->sync_period_objects);
        if (why)
            error_at(c, d->sdo[i].line, "SDO %04X:%02X: %s", d->sdo[i].write.index, d->sdo[i].write.sub, why);
    }
    for (int i = 0; i < d->number; i++) {
        const cia402_drive_cfg_t *o = &c->cfg->drives[i];
        if (d->node_id && o->node_id == d->node_id && strcmp(o->interface, d->interface) == 0)
            error_at(c, d->node_line, "NODE_ID %d on %s is also used by [CIA402_DRIVE_%d] (line %d)",
                     d->node_id, d->interface, o->number, o->node_line);
    }
}

/* Build every drive from [CIA402] and its own section. */
static void build_drives(cfg_ctx_t *c)
{
    int line_of[CIA402_MAX_DRIVES] = { 0 }, global_line = 0;
    cia402_drive_cfg_t defaults;
    char name[32];
    scan_sections(c, line_of, &global_line);
    set_defaults(&defaults);
    apply_section(c, GLOBAL_SECTION, IN_GLOBAL, &defaults);
    while (c->cfg->drive_count < CIA402_MAX_DRIVES && line_of[c->cfg->drive_count])
        c->cfg->drive_count++;
    for (int n = c->cfg->drive_count; n < CIA402_MAX_DRIVES; n++)
        if (line_of[n])
            error_at(c, line_of[n], "[CIA402_DRIVE_%d] without [CIA402_DRIVE_%d]: drive sections are numbered "
                     "from 0 without gaps", n, c->cfg->drive_count);
    if (c->cfg->drive_count == 0 && c->errors == 0)
        error_at(c, 0, "no [CIA402_DRIVE_0] section: nothing to drive");
    for (int n = 0; n < c->cfg->drive_count; n++) {
        cia402_drive_cfg_t *d = &c->cfg->drives[n];
        *d = defaults;
        d->number = n;
        d->section_line = line_of[n];
        snprintf(name, sizeof(name), DRIVE_PREFIX "%d", n);
        apply_section(c, name, IN_DRIVE, d);
        check_drive(c, d);
    }
}

/* Read and check path; returns 0, or -1 after reporting every problem. */
int cia402_cfg_load(cia402_cfg_t *cfg, const char *path, co_report_fn report, void *ctx)
{
    cfg_ctx_t c = { .cfg = cfg, .report = report, .ctx = ctx };
    memset(cfg, 0, sizeof(*cfg));
    snprintf(cfg->path, sizeof(cfg->path), "%s", path);
    cfg->sync_cob_id = CO_SYNC;
    if (strlen(path) >= sizeof(cfg->path)) {
        error_at(&c, 0, "the configuration path is longer than %d characters", CIA402_PATH_LEN - 1);
        return -1;
    }
    if (co_ini_load(&c.ini, path, report, ctx) != 0)
        return -1;
    c.errors = c.ini.errors;
    build_drives(&c);
    co_ini_free(&c.ini);
    return c.errors ? -1 : 0;
}

/* SDO = INDEX:SUB TYPE VALUE (repeatable; written in file order after the driver's own set-up) */
static void cia402_cfg_add_sdo(cfg_ctx_t *c, cia402_drive_cfg_t *d, const co_ini_entry_t *e)
{
    char why[CFG_TEXT_LEN];
    cia402_sdo_item_t *item = &d->sdo[d->sdo_count];
    if (d->sdo_count == CIA402_MAX_SDO) {
        error_at(c, e->line, "more than %d SDO lines in [CIA402_DRIVE_%d]", CIA402_MAX_SDO, d->number);
        return;
    }
    if (cia402_sdo_line_parse(e->value, &item->write, why, sizeof(why)) != 0) {
        error_at(c, e->line, "%s", why);
        return;
    }
    item->line = e->line;
    d->sdo_count++;
}
