/* cl_parse_rung.c: parses rung_N.csv (#VER/#LABEL/#COMMENT/#PREVRUNG/#NEXTRUNG and the grid). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cl_project.h"

/* Parse a whole decimal integer (optional sign, surrounding blanks); returns 0 on success. */
static int parse_int(const char *s, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);

    while (*end == ' ' || *end == '\t')
        end++;
    if (end == s || *end || v < -1000000000L || v > 1000000000L)
        return -1;
    *out = (int)v;
    return 0;
}

/* Copy a header value into a fixed buffer. */
static void copy_text(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src);
}

/* One "#KEY=value" header line. */
static int parse_header(cl_load_t *ld, cl_rung_t *r, const cl_line_t *l)
{
    const char *eq = strchr(l->text, '=');
    const char *v = eq ? eq + 1 : "";
    size_t klen = eq ? (size_t)(eq - l->text) : strlen(l->text);
    int *link = NULL;

    if (klen == 6 && strncmp(l->text, "#LABEL", 6) == 0)
        copy_text(r->label, sizeof(r->label), v);
    else if (klen == 8 && strncmp(l->text, "#COMMENT", 8) == 0)
        copy_text(r->comment, sizeof(r->comment), v);
    else if (klen == 9 && strncmp(l->text, "#PREVRUNG", 9) == 0)
        link = &r->prev;
    else if (klen == 9 && strncmp(l->text, "#NEXTRUNG", 9) == 0)
        link = &r->next;
    if (link && parse_int(v, link) < 0)
        return cl_load_error(ld, l->line, "bad rung number '%s' in %.*s", v, (int)klen, l->text);
    return 0;
}

/* One cell "TYPE-TOP-VARTYPE/VARNUM" (an index suffix "-T/N" must be 0/0). */
static int parse_cell(cl_load_t *ld, cl_cell_t *c, const char *text, int line, int x)
{
    int type, top, vt, vn, it = 0, in = 0, used = 0, n;

    n = sscanf(text, " %d-%d-%d/%d%n-%d/%d%n", &type, &top, &vt, &vn, &used, &it, &in, &used);
    if (n < 4)
        return cl_load_error(ld, line, "column %d: bad cell '%.30s' (expected "
                             "TYPE-TOP-VARTYPE/NUM)", x, text);
    while (text[used] == ' ' || text[used] == '\t')
        used++;
    if (text[used])
        return cl_load_error(ld, line, "column %d: unexpected text in cell '%.30s'", x, text);
    if (n == 6 && (it != 0 || in != 0))
        return cl_load_error(ld, line, "column %d: indexed variables are not supported", x);
    if (top != 0 && top != 1)
        return cl_load_error(ld, line, "column %d: connected-to-top flag must be 0 or 1", x);
    if (type < 0 || type > 32767 || vt < 0 || vt > 32767)
        return cl_load_error(ld, line, "column %d: type out of range in '%.30s'", x, text);
    *c = (cl_cell_t){ .type = (int16_t)type, .connected_top = (int8_t)top,
                      .var_type = (int16_t)vt, .var_num = vn };
    return 0;
}

/* One grid row of CL_RUNG_WIDTH comma-separated cells. */
static int parse_row(cl_load_t *ld, cl_rung_t *r, int y, const cl_line_t *l)
{
    char row[1024];
    char *p = row;
    int x;

    if (strlen(l->text) >= sizeof(row))
        return cl_load_error(ld, l->line, "rung row too long");
    strcpy(row, l->text);
    for (x = 0; x < CL_RUNG_WIDTH; x++) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = 0;
        if (x == CL_RUNG_WIDTH - 1 && comma && comma[1 + strspn(comma + 1, " \t")])
            return cl_load_error(ld, l->line, "more than %d cells in rung row", CL_RUNG_WIDTH);
        if (!comma && x < CL_RUNG_WIDTH - 1)
            return cl_load_error(ld, l->line, "%d cells in rung row, expected %d", x + 1,
                                 CL_RUNG_WIDTH);
        if (parse_cell(ld, &r->cells[y][x], p, l->line, x) < 0)
            return -1;
        p = comma ? comma + 1 : p + strlen(p);
    }
    return 0;
}

/* Parse rung file lines into rung number n. */
int cl_parse_rung(cl_load_t *ld, int n, const cl_line_t *lines, int count)
{
    cl_rung_t *r = &ld->m->rungs[n];
    int y = 0;

    if (r->used)
        return cl_load_error(ld, count ? lines[0].line - 1 : 0, "rung %d defined twice", n);
    memset(r, 0, sizeof(*r));
    r->used = 1;
    r->prev = r->next = -1;
    for (int i = 0; i < count; i++) {
        const cl_line_t *l = &lines[i];
        if (l->text[0] == '#') {
            if (parse_header(ld, r, l) < 0)
                return -1;
        } else if (l->text[strspn(l->text, " \t")]) {
            if (y == CL_RUNG_HEIGHT)
                return cl_load_error(ld, l->line, "more than %d rows in rung %d", CL_RUNG_HEIGHT,
                                     n);
            ld->row_lines[n * CL_RUNG_HEIGHT + y] = l->line;
            if (parse_row(ld, r, y++, l) < 0)
                return -1;
        }
    }
    if (y != CL_RUNG_HEIGHT)
        return cl_load_error(ld, count ? lines[count - 1].line : 0,
                             "rung %d has %d rows, expected %d", n, y, CL_RUNG_HEIGHT);
    return 0;
}
