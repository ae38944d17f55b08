/* mb2hal_config.c: reads [MB2HAL_INIT] and every [TRANSACTION_NN] into an mb2hal_cfg_t. */
#include "mb2hal_config.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mb2hal_log.h"
#include "mb_cfgval.h"

#define HAL_NAME_MAX 47

/* Function codes mb2hal knows: name, LinuxCNC's number for it (shown in the INIT_DEBUG log),
 * the most elements one run may carry (5 and 6 write element by element) and the VERSION needed. */
static const struct {
    int code;
    const char *name;
    int log_number;
    int max_elements;
    int min_version;
} codes[] = {
    {1, "fnct_01_read_coils", 7, 2000, 11},
    {2, "fnct_02_read_discrete_inputs", 1, 2000, 10},
    {3, "fnct_03_read_holding_registers", 2, 125, 10},
    {4, "fnct_04_read_input_registers", 3, 125, 10},
    {5, "fnct_05_write_single_coil", 8, 65536, 11},
    {6, "fnct_06_write_single_register", 4, 65536, 10},
    {15, "fnct_15_write_multiple_coils", 5, 1968, 10},
    {16, "fnct_16_write_multiple_registers", 6, 123, 10},
};
#define NCODES ((int)(sizeof(codes) / sizeof(codes[0])))

/* "fnct_03_read_holding_registers" style name of a function code. */
const char *mb2hal_code_name(int code)
{
    for (int i = 0; i < NCODES; i++)
        if (codes[i].code == code)
            return codes[i].name;
    return "?";
}

/* LinuxCNC's number for a function code, as its INIT_DEBUG log shows it. */
static int code_log_number(int code)
{
    for (int i = 0; i < NCODES; i++)
        if (codes[i].code == code)
            return codes[i].log_number;
    return 0;
}

/* Non-zero when the function code reads from the device. */
int mb2hal_code_is_read(int code)
{
    return code >= 1 && code <= 4;
}

/* Non-zero when the function code works on bits. */
int mb2hal_code_is_bits(int code)
{
    return code == 1 || code == 2 || code == 5 || code == 15;
}

/* Non-zero when name is a usable part of a HAL name. */
static int valid_name(const char *name)
{
    if (!*name)
        return 0;
    for (; *name; name++)
        if (!isalnum((unsigned char)*name) && !strchr("_-.", *name))
            return 0;
    return 1;
}

/* Reads [MB2HAL_INIT]. */
static void parse_init(mb2hal_cfg_t *cfg, mb_sec_t *s)
{
    static const char *const versions[] = {"1.0", "1.1", NULL};
    int v = 0;
    cfg->init_debug = 1;
    cfg->version = 10;
    strcpy(cfg->module_name, "mb2hal");
    if (mb_ini_section_line(s->ini, s->section) == 0) {
        mb_cfg_error(s, 0, "TOTAL_TRANSACTIONS", "section [%s] is missing", s->section);
        return;
    }
    mb_get_int(s, "INIT_DEBUG", 0, 5, &cfg->init_debug);
    if (mb_get_choice(s, "VERSION", versions, &v) == 1)
        cfg->version = v ? 11 : 10;
    if (mb_get_str(s, "HAL_MODULE_NAME", cfg->module_name, sizeof(cfg->module_name)) == 1 &&
        !valid_name(cfg->module_name))
        mb_cfg_error(s, mb_key_line(s, "HAL_MODULE_NAME"), "HAL_MODULE_NAME",
                     "'%s' is not a valid HAL name", cfg->module_name);
    mb_get_double(s, "SLOWDOWN", 0.0, 60.0, &cfg->slowdown);
    if (mb_get_int(s, "TOTAL_TRANSACTIONS", 1, MB2HAL_MAX_TX, &cfg->ntx) == 0)
        mb_cfg_missing(s, "TOTAL_TRANSACTIONS");
}

/* Reads the serial keys of a link (missing ones keep the inherited value). */
static void parse_serial(mb_sec_t *s, mb_link_cfg_t *l)
{
    static const char *const parities[] = {"none", "even", "odd", NULL};
    int p = 0;
    mb_get_str(s, "SERIAL_PORT", l->serial_port, sizeof(l->serial_port));
    mb_get_int(s, "SERIAL_BAUD", 50, 4000000, &l->serial_baud);
    mb_get_int(s, "SERIAL_BITS", 5, 8, &l->serial_bits);
    if (mb_get_choice(s, "SERIAL_PARITY", parities, &p) == 1)
        l->serial_parity = "NEO"[p];
    mb_get_int(s, "SERIAL_STOP", 1, 2, &l->serial_stop);
    mb_get_int(s, "SERIAL_DELAY_MS", 0, 60000, &l->serial_delay_ms);
    if (l->type == MB_LINK_SERIAL && !l->serial_port[0])
        mb_cfg_missing(s, "SERIAL_PORT");
    if (l->type == MB_LINK_SERIAL && !l->serial_baud)
        mb_cfg_missing(s, "SERIAL_BAUD");
}

/* Reads the link keys; a transaction inherits what it does not set from the previous one. */
static void parse_link(mb_sec_t *s, mb_tx_cfg_t *tx, int first)
{
    static const char *const types[] = {"tcp", "serial", NULL};
    int r = mb_get_choice(s, "LINK_TYPE", types, &tx->link.type);
    if (r == 0 && first)
        mb_cfg_missing(s, "LINK_TYPE");
    mb_get_str(s, "TCP_IP", tx->link.tcp_ip, sizeof(tx->link.tcp_ip));
    mb_get_int(s, "TCP_PORT", 1, 65535, &tx->link.tcp_port);
    if (tx->link.type == MB_LINK_TCP && (r == 1 || (r == 0 && !first)) && !tx->link.tcp_ip[0])
        mb_cfg_missing(s, "TCP_IP");
    parse_serial(s, &tx->link);
    if (mb_get_int(s, "MB_SLAVE_ID", 0, 255, &tx->slave_id) == 0 && first)
        mb_cfg_missing(s, "MB_SLAVE_ID");
    mb_get_int(s, "MB_RESPONSE_TIMEOUT_MS", 1, 60000, &tx->resp_timeout_ms);
    mb_get_int(s, "MB_BYTE_TIMEOUT_MS", 1, 60000, &tx->byte_timeout_ms);
}

/* Reads MB_TX_CODE. */
static int parse_code(mb2hal_cfg_t *cfg, mb_sec_t *s, mb_tx_cfg_t *tx)
{
    const char *names[NCODES + 1];
    int idx;
    for (int i = 0; i < NCODES; i++)
        names[i] = codes[i].name;
    names[NCODES] = NULL;
    int r = mb_get_choice(s, "MB_TX_CODE", names, &idx);
    if (r == 0)
        mb_cfg_missing(s, "MB_TX_CODE");
    if (r != 1)
        return -1;
    tx->code = codes[idx].code;
    if (cfg->version < codes[idx].min_version) {
        mb_cfg_error(s, mb_key_line(s, "MB_TX_CODE"), "MB_TX_CODE", "%s needs VERSION=1.1 in [MB2HAL_INIT]",
                     codes[idx].name);
        return -1;
    }
    return codes[idx].max_elements;
}

/* Splits PIN_NAMES (comma separated) into tx->pin_names; returns the count or -1. */
static int parse_pin_names(mb_sec_t *s, mb_tx_cfg_t *tx, const char *value, int line)
{
    int n = 1;
    for (const char *p = value; *p; p++)
        n += *p == ',';
    tx->pin_names = calloc((size_t)n, sizeof(*tx->pin_names));
    if (!tx->pin_names)
        return -1;
    const char *p = value;
    for (int i = 0; i < n; i++) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        while (len && isspace((unsigned char)*p)) { p++; len--; }
        while (len && isspace((unsigned char)p[len - 1]))
            len--;
        if (len == 0 || len >= MB2HAL_NAME_LEN) {
            mb_cfg_error(s, line, "PIN_NAMES", "name %d is %s", i + 1, len ? "too long" : "empty");
            return -1;
        }
        memcpy(tx->pin_names[i], p, len);
        if (!valid_name(tx->pin_names[i])) {
            mb_cfg_error(s, line, "PIN_NAMES", "'%s' is not a valid HAL name", tx->pin_names[i]);
            return -1;
        }
        for (int j = 0; j < i; j++)
            if (strcmp(tx->pin_names[j], tx->pin_names[i]) == 0) {
                mb_cfg_error(s, line, "PIN_NAMES", "'%s' is given twice", tx->pin_names[i]);
                return -1;
            }
        p = end ? end + 1 : p + len;
    }
    return n;
}

/* Reads NELEMENTS or (version 1.1) PIN_NAMES and checks the count against the code. */
static void parse_elements(mb2hal_cfg_t *cfg, mb_sec_t *s, mb_tx_cfg_t *tx, int max)
{
    mb_ini_entry_t *names = mb_ini_get(s->ini, s->section, "PIN_NAMES");
    int r = mb_get_int(s, "NELEMENTS", 1, 65536, &tx->nelements);
    int line = names ? names->line : mb_key_line(s, "NELEMENTS");
    if (names && cfg->version < 11) {
        mb_cfg_error(s, names->line, "PIN_NAMES", "needs VERSION=1.1 in [MB2HAL_INIT]");
        return;
    }
    if (names && r != 0) {
        mb_cfg_error(s, names->line, "PIN_NAMES", "give either NELEMENTS or PIN_NAMES, not both");
        return;
    }
    if (names && (tx->nelements = parse_pin_names(s, tx, names->value, names->line)) < 0)
        return;
    if (!names && r == 0)
        mb_cfg_missing(s, cfg->version >= 11 ? "NELEMENTS or PIN_NAMES" : "NELEMENTS");
    if ((!names && r != 1) || max <= 0)
        return;
    if (tx->nelements > max)
        mb_cfg_error(s, line, names ? "PIN_NAMES" : "NELEMENTS", "%s allows at most %d element%s, got %d",
                     mb2hal_code_name(tx->code), max, max == 1 ? "" : "s", tx->nelements);
    else if (tx->first_element + tx->nelements > 65536)
        mb_cfg_error(s, line, names ? "PIN_NAMES" : "NELEMENTS",
                     "FIRST_ELEMENT + %d elements passes address 65535", tx->nelements);
}

/* Longest suffix the pins of an element get (".bit-inv", ".float", ...) for tx's code and VERSION. */
static size_t pin_suffix_len(const mb2hal_cfg_t *cfg, const mb_tx_cfg_t *tx)
{
    int bits = mb2hal_code_is_bits(tx->code), read = mb2hal_code_is_read(tx->code);
    if (cfg->version < 11)
        return !bits && read ? strlen(".float") : 0;
    if (bits)
        return read ? strlen(".bit-inv") : strlen(".bit");
    return strlen(".float");
}

/* Checks that the longest pin name of tx fits in a HAL name. */
static void check_name_lengths(mb2hal_cfg_t *cfg, mb_sec_t *s, mb_tx_cfg_t *tx)
{
    size_t longest = strlen("num_errors"), suffix = pin_suffix_len(cfg, tx);
    for (int i = 0; i < tx->nelements; i++) {
        size_t len = (tx->pin_names ? strlen(tx->pin_names[i]) : 2) + suffix;
        if (len > longest)
            longest = len;
    }
    size_t total = strlen(cfg->module_name) + 1 + strlen(tx->tx_name) + 1 + longest;
    if (total > HAL_NAME_MAX)
        mb_cfg_error(s, mb_key_line(s, "HAL_TX_NAME"), "HAL_TX_NAME",
                     "pin names of '%s.%s' would pass %d characters", cfg->module_name,
                     tx->tx_name, HAL_NAME_MAX);
}

/* Reads one [TRANSACTION_NN]; tx arrives holding the inherited link settings. */
static void parse_tx(mb2hal_cfg_t *cfg, mb_sec_t *s, mb_tx_cfg_t *tx, int num)
{
    if (mb_ini_section_line(s->ini, s->section) == 0) {
        mb_cfg_error(s, mb_key_line(&(mb_sec_t){s->ini, "MB2HAL_INIT", 0}, "TOTAL_TRANSACTIONS"),
                     "TOTAL_TRANSACTIONS", "section [%s] is missing", s->section);
        return;
    }
    parse_link(s, tx, num == 0);
    int max = parse_code(cfg, s, tx);
    if (mb_get_int(s, "FIRST_ELEMENT", 0, 65535, &tx->first_element) == 0)
        mb_cfg_missing(s, "FIRST_ELEMENT");
    parse_elements(cfg, s, tx, max);
    snprintf(tx->tx_name, sizeof(tx->tx_name), "%02d", num);
    if (mb_get_str(s, "HAL_TX_NAME", tx->tx_name, sizeof(tx->tx_name)) == 1 && !valid_name(tx->tx_name))
        mb_cfg_error(s, mb_key_line(s, "HAL_TX_NAME"), "HAL_TX_NAME", "'%s' is not a valid HAL name",
                     tx->tx_name);
    for (int i = 0; i < num; i++)
        if (strcmp(cfg->tx[i].tx_name, tx->tx_name) == 0)
            mb_cfg_error(s, mb_key_line(s, "HAL_TX_NAME"), "HAL_TX_NAME", "'%s' is already used by [%s]",
                         tx->tx_name, cfg->tx[i].section);
    check_name_lengths(cfg, s, tx);
    mb_get_double(s, "MAX_UPDATE_RATE", 0.0, 1e6, &tx->max_update_rate);
    tx->debug = cfg->init_debug;
    mb_get_int(s, "DEBUG", 0, 5, &tx->debug);
    tx->version = cfg->version;
}

/* Sets tx to the defaults, or to what the previous transaction passes on. */
static void init_tx(mb_tx_cfg_t *tx, const mb_tx_cfg_t *prev, int num)
{
    memset(tx, 0, sizeof(*tx));
    snprintf(tx->section, sizeof(tx->section), "TRANSACTION_%02d", num);
    if (prev) {
        tx->link = prev->link;
        tx->slave_id = prev->slave_id;
        tx->resp_timeout_ms = prev->resp_timeout_ms;
        tx->byte_timeout_ms = prev->byte_timeout_ms;
        return;
    }
    tx->link.tcp_port = 502;
    tx->link.serial_bits = 8;
    tx->link.serial_stop = 1;
    tx->link.serial_parity = 'N';
    tx->resp_timeout_ms = 500;
    tx->byte_timeout_ms = 500;
}

/* Logs [MB2HAL_INIT] the way LinuxCNC's INIT_DEBUG=3 shows it. */
static void log_init(const mb2hal_cfg_t *cfg)
{
    const char *w = "parse_common_section";
    int d = cfg->init_debug;
    mb_log(d, MB_LOG_DEBUG, w, "[MB2HAL_INIT] [INIT_DEBUG] [%d]", d);
    mb_log(d, MB_LOG_DEBUG, w, "[MB2HAL_INIT] [VERSION] [%d]", 1000 * (cfg->version / 10) + cfg->version % 10);
    mb_log(d, MB_LOG_DEBUG, w, "[MB2HAL_INIT] [HAL_MODULE_NAME] [%s]", cfg->module_name);
    mb_log(d, MB_LOG_DEBUG, w, "[MB2HAL_INIT] [SLOWDOWN] [%0.3f]", cfg->slowdown);
    mb_log(d, MB_LOG_DEBUG, w, "[MB2HAL_INIT] [TOTAL_TRANSACTIONS] [%d]", cfg->ntx);
}

/* Logs the link keys of a transaction (serial or TCP subsection). */
static void log_link(int d, const mb_tx_cfg_t *tx)
{
    static const char *const parities[] = {['N'] = "none", ['E'] = "even", ['O'] = "odd"};
    const mb_link_cfg_t *l = &tx->link;
    int serial = l->type == MB_LINK_SERIAL;
    mb_log(d, MB_LOG_DEBUG, "parse_transaction_section", "[%s] [LINK_TYPE] [%s] [%d]", tx->section,
           serial ? "serial" : "tcp", serial ? MB_LOG_LINK_RTU : MB_LOG_LINK_TCP);
    if (!serial) {
        mb_log(d, MB_LOG_DEBUG, "parse_tcp_subsection", "[%s] [TCP_IP] [%s]", tx->section, l->tcp_ip);
        mb_log(d, MB_LOG_DEBUG, "parse_tcp_subsection", "[%s] [TCP_PORT] [%d]", tx->section, l->tcp_port);
        return;
    }
    const char *w = "parse_serial_subsection";
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_PORT] [%s]", tx->section, l->serial_port);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_BAUD] [%d]", tx->section, l->serial_baud);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_BITS] [%d]", tx->section, l->serial_bits);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_PARITY] [%s]", tx->section, parities[(unsigned char)l->serial_parity]);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_STOP] [%d]", tx->section, l->serial_stop);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [SERIAL_DELAY_MS] [%d]", tx->section, l->serial_delay_ms);
}

/* Logs one parsed transaction the way LinuxCNC's INIT_DEBUG=3 shows it. */
static void log_tx(const mb2hal_cfg_t *cfg, const mb_tx_cfg_t *tx, int num)
{
    const char *w = "parse_transaction_section";
    int d = cfg->init_debug;
    log_link(d, tx);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [MB_SLAVE_ID] [%d]", tx->section, tx->slave_id);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [FIRST_ELEMENT] [%d]", tx->section, tx->first_element);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [NELEMENTS] [%d]", tx->section, tx->nelements);
    for (int i = 0; tx->pin_names && i < tx->nelements; i++)
        mb_log(d, MB_LOG_DEBUG, w, "[%s] [PIN_NAMES] [%s]", tx->section, tx->pin_names[i]);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [MAX_UPDATE_RATE] [%0.3f]", tx->section, tx->max_update_rate);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [MB_RESPONSE_TIMEOUT_MS] [%d]", tx->section, tx->resp_timeout_ms);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [MB_BYTE_TIMEOUT_MS] [%d]", tx->section, tx->byte_timeout_ms);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [DEBUG] [%d]", tx->section, tx->debug);
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [MB_TX_CODE] [%s] [%d]", tx->section, mb2hal_code_name(tx->code),
           code_log_number(tx->code));
    mb_log(d, MB_LOG_DEBUG, w, "[%s] [HAL_TX_NAME] [%s]", tx->section, tx->tx_name);
    mb_log(d, MB_LOG_OK, "parse_ini_file", "parse_transaction_section %d OK", num);
}

/* Warns about keys no lookup asked for (typos, unused sections). */
static void warn_unused(mb2hal_cfg_t *cfg, mb_ini_t *ini)
{
    for (int i = 0; cfg->init_debug >= 1 && i < ini->count; i++) {
        mb_ini_entry_t *e = &ini->entries[i];
        if (!e->used)
            fprintf(stderr, "mb2hal: %s:%d: [%s] %s: unknown key or unused section, ignored\n",
                    ini->path, e->line, e->section, e->key);
    }
}

/* Parses path into cfg; returns 0, or -1 after printing every error found. */
int mb2hal_config_load(mb2hal_cfg_t *cfg, const char *path)
{
    mb_ini_t ini;
    memset(cfg, 0, sizeof(*cfg));
    if (mb_ini_load(&ini, path))
        return -1;
    mb_sec_t init = {&ini, "MB2HAL_INIT", 0};
    parse_init(cfg, &init);
    int errors = init.errors;
    if (!errors)
        log_init(cfg);
    for (int i = 0; i < cfg->ntx; i++) {
        mb_tx_cfg_t *tx = &cfg->tx[i];
        init_tx(tx, i ? &cfg->tx[i - 1] : NULL, i);
        mb_sec_t s = {&ini, tx->section, 0};
        parse_tx(cfg, &s, tx, i);
        if (!s.errors && !errors)
            log_tx(cfg, tx, i);
        errors += s.errors;
    }
    if (!errors)
        warn_unused(cfg, &ini);
    mb_ini_free(&ini);
    if (errors)
        mb2hal_config_free(cfg);
    return errors ? -1 : 0;
}

/* Frees the pin name lists of cfg. */
void mb2hal_config_free(mb2hal_cfg_t *cfg)
{
    for (int i = 0; i < MB2HAL_MAX_TX; i++) {
        free(cfg->tx[i].pin_names);
        cfg->tx[i].pin_names = NULL;
    }
}
