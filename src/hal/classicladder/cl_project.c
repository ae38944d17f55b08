/* cl_project.c: splits a .clp project into its embedded files and dispatches them. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cl_project.h"

#define CLP_BEGIN "_FILES_CLASSICLADDER"
#define CLP_END "_/FILES_CLASSICLADDER"
#define CLP_MAX_BYTES (16 * 1024 * 1024)

/* Record an error "FILE:LINE: message" (line 0: no line); always returns -1. */
int cl_load_error(cl_load_t *ld, int line, const char *fmt, ...)
{
    char msg[CL_ERR_LEN / 2];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof(msg), fmt, ap);
    va_end(ap);
    if (line > 0)
        snprintf(ld->err, sizeof(ld->err), "%.200s:%d: %s", ld->path, line, msg);
    else
        snprintf(ld->err, sizeof(ld->err), "%.200s: %s", ld->path, msg);
    return -1;
}

/* Read the whole file as a NUL-terminated buffer. */
static char *read_file(cl_load_t *ld)
{
    FILE *f = fopen(ld->path, "rb");
    char *buf = NULL;
    long size = -1;
    size_t n = 0;

    if (!f) {
        cl_load_error(ld, 0, "cannot open: %s", strerror(errno));
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    rewind(f);
    if (size >= 0 && size <= CLP_MAX_BYTES)
        buf = malloc((size_t)size + 1);
    if (buf)
        n = fread(buf, 1, (size_t)size, f);
    fclose(f);
    if (!buf || n != (size_t)size) {
        free(buf);
        cl_load_error(ld, 0, "cannot read (not a regular file of at most %d bytes)",
                      CLP_MAX_BYTES);
        return NULL;
    }
    buf[n] = 0;
    if (memchr(buf, 0, n)) {
        free(buf);
        cl_load_error(ld, 0, "binary data (NUL byte) in project file");
        return NULL;
    }
    return buf;
}

/* Split buf into lines (CR LF or LF), numbering from 1; returns the count or -1. */
static int split_lines(char *buf, cl_line_t **out)
{
    int count = 1, n = 0;
    char *p;

    for (p = buf; *p; p++)
        count += *p == '\n';
    *out = malloc(sizeof(cl_line_t) * (size_t)count);
    if (!*out)
        return -1;
    for (p = buf;;) {
        char *eol = strchr(p, '\n');
        size_t len;

        (*out)[n] = (cl_line_t){ p, n + 1 };
        n++;
        if (eol)
            *eol = 0;
        len = strlen(p);
        if (len > 0 && p[len - 1] == '\r')
            p[len - 1] = 0;
        if (!eol)
            return n;
        p = eol + 1;
    }
}

/* Hand one embedded file to its parser; unknown files (I/O, Modbus, logs) are skipped. */
static int dispatch(cl_load_t *ld, const char *name, const cl_line_t *lines, int count, int at)
{
    int rung;
    char tail;

    if (sscanf(name, "rung_%d.csv%c", &rung, &tail) == 1 && strncmp(name, "rung_", 5) == 0) {
        if (rung < 0 || rung >= ld->m->hdr->sizes[CL_N_RUNGS])
            return cl_load_error(ld, at, "rung %d beyond numRungs=%d", rung,
                                 ld->m->hdr->sizes[CL_N_RUNGS]);
        ld->rung_lines[rung] = at;
        return cl_parse_rung(ld, rung, lines, count);
    }
    return cl_parse_table(ld, name, lines, count);
}

/* Walk the _FILE-name ... _/FILE-name blocks between the project markers. */
static int walk_files(cl_load_t *ld, cl_line_t *lines, int count)
{
    int i = 0;

    while (i < count && lines[i].text[0] == 0)
        i++;
    if (i == count || strcmp(lines[i].text, CLP_BEGIN) != 0)
        return cl_load_error(ld, i < count ? lines[i].line : 0,
                             "not a ClassicLadder project: expected '%s'", CLP_BEGIN);
    for (i++; i < count; i++) {
        const char *t = lines[i].text;
        int start = i, end;
        char close[300];

        if (t[0] == 0)
            continue;
        if (strcmp(t, CLP_END) == 0)
            return 0;
        if (strncmp(t, "_FILE-", 6) != 0 || !t[6])
            return cl_load_error(ld, lines[i].line, "expected '_FILE-name' or '%s', got '%.40s'",
                                 CLP_END, t);
        snprintf(close, sizeof(close), "_/FILE-%s", t + 6);
        for (end = start + 1; end < count && strcmp(lines[end].text, close) != 0; end++)
            ;
        if (end == count)
            return cl_load_error(ld, lines[start].line, "'%.40s' has no closing '%.40s'", t, close);
        if (dispatch(ld, t + 6, lines + start + 1, end - start - 1, lines[start].line) < 0)
            return -1;
        i = end;
    }
    return cl_load_error(ld, lines[count - 1].line, "missing '%s' at end of file", CLP_END);
}

/* Default section when the project has none: one main ladder from the lowest rung. */
static void default_section(cl_mem_t *m)
{
    int first = -1;

    for (int r = m->hdr->sizes[CL_N_RUNGS] - 1; r >= 0; r--)
        if (m->rungs[r].used)
            first = r;
    if (first < 0 || m->hdr->sizes[CL_N_SECTIONS] < 1)
        return;
    m->sections[0] = (cl_section_t){ 1, 0, -1, first, -1, "Prog1" };
}

/* Allocate the line-number tables of the loader; returns 0 or -1. */
static int alloc_lines(cl_load_t *ld)
{
    const int32_t *n = ld->m->hdr->sizes;

    ld->rung_lines = calloc((size_t)n[CL_N_RUNGS] + 1, sizeof(int));
    ld->row_lines = calloc((size_t)n[CL_N_RUNGS] * CL_RUNG_HEIGHT + 1, sizeof(int));
    ld->section_lines = calloc((size_t)n[CL_N_SECTIONS] + 1, sizeof(int));
    if (ld->rung_lines && ld->row_lines && ld->section_lines)
        return 0;
    return cl_load_error(ld, 0, "out of memory");
}

/* Parse and check the text in buf. */
static int load_text(cl_load_t *ld, char *buf)
{
    cl_line_t *lines = NULL;
    int rc = -1, count = split_lines(buf, &lines);

    if (count < 0)
        cl_load_error(ld, 0, "out of memory");
    else if (walk_files(ld, lines, count) == 0) {
        if (!ld->have_sections)
            default_section(ld->m);
        rc = cl_check_project(ld);
    }
    free(lines);
    return rc;
}

/* Load project path into m (program cleared first); returns 0 or -1 with err set. */
int cl_project_load(cl_mem_t *m, const char *path, char *err, int errlen)
{
    cl_load_t ld = { .m = m, .path = path };
    char *buf = NULL;
    int rc = -1;

    cl_clear_program(m);
    if (alloc_lines(&ld) == 0 && (buf = read_file(&ld)) != NULL)
        rc = load_text(&ld, buf);
    free(ld.rung_lines);
    free(ld.row_lines);
    free(ld.section_lines);
    free(buf);
    if (rc < 0)
        snprintf(err, errlen, "%s", ld.err);
    return rc;
}
