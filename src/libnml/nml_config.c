/* nml_config.c: parsing LinuxCNC .nml files (B and P lines) with file:line errors. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "nml.h"
#include "rtapi_instance.h"

#define MAX_TOKENS 32
#define MAX_KEY 0x00FFFFFF  /* the top byte of a key carries the instance */
#define MAX_SIZE (64u << 20)
#define MIN_SIZE 64u

/* State while reading one file. */
typedef struct parse {
    nml_config_t *cfg;
    const char *path;
    int line;
    char *err;
    size_t errlen;
} parse_t;

/* Report "path:line: what" into err; always -EINVAL. */
static int fail(parse_t *p, const char *fmt, ...)
{
    va_list ap;
    int len = snprintf(p->err, p->errlen, "%s:%d: ", p->path, p->line);

    va_start(ap, fmt);
    if (len >= 0 && (size_t)len < p->errlen)
        vsnprintf(p->err + len, p->errlen - len, fmt, ap);
    va_end(ap);
    return -EINVAL;
}

/* Keep a warning "path:line: warning: what"; -ENOMEM when out of memory. */
static int warn(parse_t *p, const char *fmt, ...)
{
    char text[512];
    char **grown;
    va_list ap;
    int len = snprintf(text, sizeof text, "%s:%d: warning: ", p->path, p->line);

    va_start(ap, fmt);
    if (len >= 0 && (size_t)len < sizeof text)
        vsnprintf(text + len, sizeof text - len, fmt, ap);
    va_end(ap);
    grown = realloc(p->cfg->warnings, (p->cfg->n_warnings + 1) * sizeof *grown);
    if (!grown)
        return -ENOMEM;
    p->cfg->warnings = grown;
    grown[p->cfg->n_warnings] = strdup(text);
    if (!grown[p->cfg->n_warnings])
        return -ENOMEM;
    p->cfg->n_warnings++;
    return 0;
}

/* Parse a whole integer token (decimal, or 0x hex); 0 or -EINVAL. */
static int parse_int(const char *text, long *value)
{
    char *end;

    errno = 0;
    *value = strtol(text, &end, 0);
    return (errno || end == text || *end) ? -EINVAL : 0;
}

/* Copy a name token; fails when it does not fit. */
static int copy_name(parse_t *p, char *dst, size_t size, const char *text, const char *what)
{
    if (strlen(text) >= size)
        return fail(p, "%s '%s' is too long (at most %zu characters)", what, text, size - 1);
    strcpy(dst, text);
    return 0;
}

/* Integer column `what` within [min, max]. */
static int int_column(parse_t *p, const char *text, const char *what, long min, long max,
                      long *value)
{
    if (parse_int(text, value) < 0)
        return fail(p, "%s '%s' is not an integer", what, text);
    if (*value < min || *value > max)
        return fail(p, "%s %ld is out of range %ld..%ld", what, *value, min, max);
    return 0;
}

/* One option of a B line: queue, confirm_write, serial; others are noted and ignored. */
static int buffer_option(parse_t *p, nml_buffer_cfg_t *b, const char *opt)
{
    static const char *const ignored[] = {"xdr", "ascii", "disp", "packed", "diag",
                                          "neutral", "nonneutral", "split", NULL};
    int i;

    if (!strcasecmp(opt, "queue"))
        b->flags |= NML_FLAG_QUEUE;
    else if (!strcasecmp(opt, "confirm_write"))
        b->flags |= NML_FLAG_CONFIRM_WRITE;
    else if (!strcasecmp(opt, "serial"))
        b->flags |= NML_FLAG_SERIAL;
    else if (strchr(opt, '='))
        return 0; /* TCP=5005, bsem=..., vme_addr=...: network and hardware settings */
    else {
        for (i = 0; ignored[i]; i++)
            if (!strcasecmp(opt, ignored[i]))
                return 0;
        return warn(p, "option '%s' of buffer '%s' is unknown and ignored", opt, b->name);
    }
    return 0;
}

/* Check that a new buffer's name and key are unique. */
static int buffer_unique(parse_t *p, const nml_buffer_cfg_t *b)
{
    int i;

    for (i = 0; i < p->cfg->n_buffers; i++) {
        const nml_buffer_cfg_t *o = &p->cfg->buffers[i];
        if (!strcmp(o->name, b->name))
            return fail(p, "buffer '%s' is already defined on line %d", b->name, o->line);
        if (o->key == b->key)
            return fail(p, "key %d of buffer '%s' is already used by buffer '%s' (line %d)",
                        b->key, b->name, o->name, o->line);
    }
    return 0;
}

/* B name type host size neut rpc# buffer# max_procs key [options...] */
static int parse_b_line(parse_t *p, char **tok, int n)
{
    nml_buffer_cfg_t b;
    nml_buffer_cfg_t *grown;
    long v;
    int i, rc;

    if (n < 10)
        return fail(p, "buffer line needs 10 columns (B name type host size neut rpc# "
                       "buffer# max_procs key), found %d", n);
    memset(&b, 0, sizeof b);
    b.line = p->line;
    if ((rc = copy_name(p, b.name, sizeof b.name, tok[1], "buffer name")) < 0)
        return rc;
    if (strcasecmp(tok[2], "SHMEM"))
        return fail(p, "buffer '%s': type '%s' is not supported (only SHMEM)", b.name, tok[2]);
    if ((rc = copy_name(p, b.host, sizeof b.host, tok[3], "host")) < 0)
        return rc;
    if ((rc = int_column(p, tok[4], "size", MIN_SIZE, MAX_SIZE, &v)) < 0)
        return rc;
    b.size = (uint32_t)v;
    if ((rc = int_column(p, tok[5], "neutral flag", 0, 1, &v)) < 0)
        return rc;
    b.neutral = (int)v;
    if ((rc = int_column(p, tok[6], "rpc number", 0, 0x7fffffff, &v)) < 0)
        return rc;
    if ((rc = int_column(p, tok[7], "buffer number", 0, 0x7fffffff, &v)) < 0)
        return rc;
    b.buffer_number = (int)v;
    if ((rc = int_column(p, tok[8], "max_procs", 1, 0x7fffffff, &v)) < 0)
        return rc;
    b.max_procs = (int)v;
    if ((rc = int_column(p, tok[9], "key", 1, MAX_KEY, &v)) < 0)
        return rc;
    b.key = (int)v;
    for (i = 10; i < n; i++)
        if ((rc = buffer_option(p, &b, tok[i])) < 0)
            return rc;
    if ((rc = buffer_unique(p, &b)) < 0)
        return rc;
    grown = realloc(p->cfg->buffers, (p->cfg->n_buffers + 1) * sizeof *grown);
    if (!grown)
        return -ENOMEM;
    p->cfg->buffers = grown;
    grown[p->cfg->n_buffers++] = b;
    return 0;
}

/* Access column: R, W or RW. */
static int parse_access(parse_t *p, const char *text, unsigned *access)
{
    if (!strcasecmp(text, "R"))
        *access = NML_ACCESS_R;
    else if (!strcasecmp(text, "W"))
        *access = NML_ACCESS_W;
    else if (!strcasecmp(text, "RW") || !strcasecmp(text, "WR"))
        *access = NML_ACCESS_RW;
    else
        return fail(p, "access '%s' must be R, W or RW", text);
    return 0;
}

/* Timeout column: seconds >= 0, or INF. */
static int parse_timeout(parse_t *p, const char *text, double *timeout_s)
{
    char *end;

    if (!strcasecmp(text, "INF") || !strcasecmp(text, "INFINITE")) {
        *timeout_s = -1.0;
        return 0;
    }
    *timeout_s = strtod(text, &end);
    if (end == text || *end || !isfinite(*timeout_s) || *timeout_s < 0)
        return fail(p, "timeout '%s' must be a number of seconds >= 0 or INF", text);
    return 0;
}

/* Process-line columns after the name and buffer. */
static int process_columns(parse_t *p, char **tok, nml_process_cfg_t *pr)
{
    long v;
    int rc;

    if (!strcasecmp(tok[3], "REMOTE"))
        pr->remote = 1;
    else if (strcasecmp(tok[3], "LOCAL") && strcasecmp(tok[3], "AUTO"))
        return fail(p, "process type '%s' must be LOCAL or REMOTE", tok[3]);
    if ((rc = copy_name(p, pr->host, sizeof pr->host, tok[4], "host")) < 0)
        return rc;
    if ((rc = parse_access(p, tok[5], &pr->access)) < 0)
        return rc;
    if ((rc = int_column(p, tok[6], "server flag", 0, 2, &v)) < 0)
        return rc;
    pr->server = (int)v;
    if ((rc = parse_timeout(p, tok[7], &pr->timeout_s)) < 0)
        return rc;
    if ((rc = int_column(p, tok[8], "master flag", 0, 1, &v)) < 0)
        return rc;
    pr->master = (int)v;
    if ((rc = int_column(p, tok[9], "connection number", 0, 0x7fffffff, &v)) < 0)
        return rc;
    pr->connection_number = (int)v;
    return 0;
}

/* P name buffer LOCAL|REMOTE host R|W|RW server timeout master c_num */
static int parse_p_line(parse_t *p, char **tok, int n)
{
    nml_process_cfg_t pr;
    nml_process_cfg_t *grown;
    int i, rc;

    if (n < 10)
        return fail(p, "process line needs 10 columns (P name buffer type host access "
                       "server timeout master c_num), found %d", n);
    memset(&pr, 0, sizeof pr);
    pr.line = p->line;
    if ((rc = copy_name(p, pr.name, sizeof pr.name, tok[1], "process name")) < 0 ||
        (rc = copy_name(p, pr.buffer, sizeof pr.buffer, tok[2], "buffer name")) < 0 ||
        (rc = process_columns(p, tok, &pr)) < 0)
        return rc;
    for (i = 0; i < p->cfg->n_processes; i++) {
        const nml_process_cfg_t *o = &p->cfg->processes[i];
        if (!strcmp(o->name, pr.name) && !strcmp(o->buffer, pr.buffer))
            return fail(p, "process '%s' already has a line for buffer '%s' (line %d)",
                        pr.name, pr.buffer, o->line);
    }
    grown = realloc(p->cfg->processes, (p->cfg->n_processes + 1) * sizeof *grown);
    if (!grown)
        return -ENOMEM;
    p->cfg->processes = grown;
    grown[p->cfg->n_processes++] = pr;
    return 0;
}

/* Split a line (comment already removed) into whitespace separated tokens. */
static int tokenize(char *line, char **tok)
{
    int n = 0;
    char *save = NULL;
    char *t = strtok_r(line, " \t\r\n\v\f", &save);

    while (t && n < MAX_TOKENS) {
        tok[n++] = t;
        t = strtok_r(NULL, " \t\r\n\v\f", &save);
    }
    return n;
}

/* One line of the file. */
static int parse_line(parse_t *p, char *line)
{
    char *tok[MAX_TOKENS];
    char *hash = strchr(line, '#');
    int n;

    if (hash)
        *hash = '\0';
    n = tokenize(line, tok);
    if (n == 0)
        return 0;
    if (!strcmp(tok[0], "B"))
        return parse_b_line(p, tok, n);
    if (!strcmp(tok[0], "P"))
        return parse_p_line(p, tok, n);
    return fail(p, "line must start with B (buffer) or P (process), not '%s'", tok[0]);
}

/* Every P line must name a known buffer (or `default`). */
static int check_processes(parse_t *p)
{
    int i;

    for (i = 0; i < p->cfg->n_processes; i++) {
        const nml_process_cfg_t *pr = &p->cfg->processes[i];
        if (strcmp(pr->buffer, "default") && !nml_config_buffer(p->cfg, pr->buffer)) {
            p->line = pr->line;
            return fail(p, "process '%s' names unknown buffer '%s'", pr->name, pr->buffer);
        }
    }
    return 0;
}

/* Read and parse every line of the open file. */
static int parse_file(parse_t *p, FILE *f)
{
    char *line = NULL;
    size_t cap = 0;
    int rc = 0;

    while (rc == 0 && getline(&line, &cap, f) >= 0) {
        p->line++;
        rc = parse_line(p, line);
    }
    free(line);
    if (rc == -ENOMEM)
        snprintf(p->err, p->errlen, "%s: out of memory", p->path);
    return rc < 0 ? rc : check_processes(p);
}

/* Parse a .nml file. */
nml_config_t *nml_config_load(const char *path, char *err, size_t errlen)
{
    parse_t p = {NULL, path, 0, err, errlen};
    FILE *f = fopen(path, "r");
    int rc;

    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    p.cfg = calloc(1, sizeof *p.cfg);
    if (!p.cfg || !(p.cfg->path = strdup(path))) {
        snprintf(err, errlen, "%s: out of memory", path);
        fclose(f);
        nml_config_free(p.cfg);
        return NULL;
    }
    rc = parse_file(&p, f);
    fclose(f);
    if (rc < 0) {
        nml_config_free(p.cfg);
        errno = -rc;
        return NULL;
    }
    return p.cfg;
}

/* Free a parsed file. */
void nml_config_free(nml_config_t *cfg)
{
    int i;

    if (!cfg)
        return;
    for (i = 0; i < cfg->n_warnings; i++)
        free(cfg->warnings[i]);
    free(cfg->warnings);
    free(cfg->buffers);
    free(cfg->processes);
    free(cfg->path);
    free(cfg);
}

/* B line by name. */
const nml_buffer_cfg_t *nml_config_buffer(const nml_config_t *cfg, const char *name)
{
    int i;

    for (i = 0; i < cfg->n_buffers; i++)
        if (!strcmp(cfg->buffers[i].name, name))
            return &cfg->buffers[i];
    return NULL;
}

/* P line of a process for a buffer, falling back to its `default` line. */
const nml_process_cfg_t *nml_config_process(const nml_config_t *cfg, const char *process,
                                            const char *buffer)
{
    const nml_process_cfg_t *fallback = NULL;
    int i;

    for (i = 0; i < cfg->n_processes; i++) {
        const nml_process_cfg_t *pr = &cfg->processes[i];
        if (strcmp(pr->name, process))
            continue;
        if (!strcmp(pr->buffer, buffer))
            return pr;
        if (!strcmp(pr->buffer, "default"))
            fallback = pr;
    }
    return fallback;
}

/* Instance key of a buffer. */
int nml_buffer_key(const nml_buffer_cfg_t *buffer)
{
    return rtapi_instance_key(buffer->key);
}
