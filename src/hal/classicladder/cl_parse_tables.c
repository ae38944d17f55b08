/* cl_parse_tables.c: timers, monostables, counters, IEC timers, expressions, sections, symbols. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cl_project.h"
#include "cl_expr.h"

/* Handler of one table line; index counts the data lines of the file from 0. */
typedef int (*line_fn)(cl_load_t *ld, const cl_line_t *l, int index);

/* Comma-separated integers of a line; returns how many, -1 when a field is not a number. */
static int parse_ints(const char *s, int *vals, int max)
{
    int n = 0;

    for (;;) {
        char *end;
        long v = strtol(s, &end, 10);
        while (*end == ' ' || *end == '\t')
            end++;
        if (end == s || n == max || v < -2000000000L || v > 2000000000L)
            return -1;
        vals[n++] = (int)v;
        if (*end == 0)
            return n;
        if (*end != ',')
            return -1;
        s = end + 1;
    }
}

/* Integers of a line that must hold exactly want fields. */
static int want_ints(cl_load_t *ld, const cl_line_t *l, int *vals, int want, const char *what)
{
    if (parse_ints(l->text, vals, want) != want)
        return cl_load_error(ld, l->line, "expected %s", what);
    return 0;
}

/* Check a time base in milliseconds. */
static int check_base(cl_load_t *ld, const cl_line_t *l, int base, int preset)
{
    if (base <= 0)
        return cl_load_error(ld, l->line, "time base must be a positive number of ms, got %d",
                             base);
    if (preset < 0)
        return cl_load_error(ld, l->line, "preset must not be negative, got %d", preset);
    return 0;
}

/* timers.csv: "base_ms,preset". */
static int timer_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    int v[2];
    if (want_ints(ld, l, v, 2, "'base,preset'") < 0 || check_base(ld, l, v[0], v[1]) < 0)
        return -1;
    if (i < ld->m->hdr->sizes[CL_N_TIMERS])
        ld->m->timers[i] = (cl_timer_t){ .base_ms = v[0], .preset = v[1] };
    return 0;
}

/* monostables.csv: "base_ms,preset". */
static int mono_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    int v[2];
    if (want_ints(ld, l, v, 2, "'base,preset'") < 0 || check_base(ld, l, v[0], v[1]) < 0)
        return -1;
    if (i < ld->m->hdr->sizes[CL_N_MONOSTABLES])
        ld->m->monos[i] = (cl_mono_t){ .base_ms = v[0], .preset = v[1] };
    return 0;
}

/* counters.csv: "preset". */
static int counter_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    int v[1];
    if (want_ints(ld, l, v, 1, "'preset'") < 0)
        return -1;
    if (v[0] < 0 || v[0] > CL_COUNTER_MAX)
        return cl_load_error(ld, l->line, "counter preset %d outside 0..%d", v[0], CL_COUNTER_MAX);
    if (i < ld->m->hdr->sizes[CL_N_COUNTERS])
        ld->m->counters[i] = (cl_counter_t){ .preset = v[0] };
    return 0;
}

/* timers_iec.csv: "base_ms,preset,mode" with mode 0 TON, 1 TOF, 2 TP. */
static int timer_iec_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    int v[3];
    if (want_ints(ld, l, v, 3, "'base,preset,mode'") < 0 || check_base(ld, l, v[0], v[1]) < 0)
        return -1;
    if (v[2] < 0 || v[2] > 2)
        return cl_load_error(ld, l->line, "IEC timer mode must be 0 (TON), 1 (TOF) or 2 (TP)");
    if (i < ld->m->hdr->sizes[CL_N_TIMERS_IEC])
        ld->m->timers_iec[i] = (cl_timer_iec_t){ .base_ms = v[0], .preset = v[1], .mode = v[2] };
    return 0;
}

/* arithmetic_expressions.csv: "NNNN,expression" (empty expressions are unused slots). */
static int arithm_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    char *end, err[200];
    long n = strtol(l->text, &end, 10);
    const char *text = end + 1;

    (void)i;
    if (end == l->text || *end != ',' || n < 0)
        return cl_load_error(ld, l->line, "expected 'number,expression'");
    if (n >= ld->m->hdr->sizes[CL_N_ARITHM] || !text[strspn(text, " \t")])
        return 0;
    if (cl_expr_compile(ld->m, text, &ld->m->arithm[n], err, sizeof(err)) < 0)
        return cl_load_error(ld, l->line, "expression %ld: %s", n, err);
    if (ld->m->arithm[n].count == 0)
        return cl_load_error(ld, l->line, "expression %ld is empty", n);
    return 0;
}

/* sections.csv data line: "num,language,subroutine,first_rung,last_rung,sequential_page". */
static int section_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    int v[6];
    cl_section_t *s;

    (void)i;
    if (want_ints(ld, l, v, 6, "'number,language,subroutine,first_rung,last_rung,page'") < 0)
        return -1;
    if (v[0] < 0 || v[0] >= ld->m->hdr->sizes[CL_N_SECTIONS])
        return cl_load_error(ld, l->line, "section %d beyond numSections=%d", v[0],
                             ld->m->hdr->sizes[CL_N_SECTIONS]);
    if (v[1] == 1)
        return cl_load_error(ld, l->line, "section %d: sequential (grafcet) sections are not "
                             "supported", v[0]);
    if (v[1] != 0)
        return cl_load_error(ld, l->line, "section %d: unknown language %d", v[0], v[1]);
    s = &ld->m->sections[v[0]];
    ld->section_lines[v[0]] = l->line;
    s->used = 1;
    s->language = v[1];
    s->sr_number = v[2];
    s->first_rung = v[3];
    s->last_rung = v[4];
    ld->have_sections = 1;
    return 0;
}

/* sections.csv "#NAMEnnn=name" header. */
static int section_name(cl_load_t *ld, const cl_line_t *l)
{
    int n, used = 0;
    if (sscanf(l->text, "#NAME%d=%n", &n, &used) != 1 || used == 0)
        return 0;
    if (n >= 0 && n < ld->m->hdr->sizes[CL_N_SECTIONS])
        snprintf(ld->m->sections[n].name, CL_SECTION_NAME_LEN, "%s", l->text + used);
    return 0;
}

/* symbols.csv: "%VAR,symbol,comment". */
static int symbol_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    char var[CL_SYMBOL_VAR_LEN] = "", sym[CL_SYMBOL_NAME_LEN] = "";
    cl_symbol_t *s;
    const char *c1 = strchr(l->text, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;

    if (!c1 || l->text[0] != '%')
        return cl_load_error(ld, l->line, "expected '%%VARIABLE,symbol,comment'");
    if (i >= ld->m->hdr->sizes[CL_N_SYMBOLS])
        return cl_load_error(ld, l->line, "more symbols than numSymbols=%d",
                             ld->m->hdr->sizes[CL_N_SYMBOLS]);
    snprintf(var, sizeof(var), "%.*s", (int)(c1 - l->text), l->text);
    snprintf(sym, sizeof(sym), "%.*s", (int)(c2 ? c2 - c1 - 1 : (long)strlen(c1 + 1)), c1 + 1);
    s = &ld->m->symbols[i];
    memcpy(s->var, var, sizeof(var));
    memcpy(s->symbol, sym, sizeof(sym));
    snprintf(s->comment, sizeof(s->comment), "%s", c2 ? c2 + 1 : "");
    return 0;
}

/* general.txt: "KEY=value" settings (sizes and refresh period are informational here). */
static int general_line(cl_load_t *ld, const cl_line_t *l, int i)
{
    (void)i;
    if (!strchr(l->text, '='))
        return cl_load_error(ld, l->line, "expected 'KEY=value'");
    return 0;
}

/* Run fn over the data lines, skipping blanks, ';' comments and '#' headers. */
static int each_line(cl_load_t *ld, const cl_line_t *lines, int count, line_fn fn, int names)
{
    int index = 0;

    for (int k = 0; k < count; k++) {
        const cl_line_t *l = &lines[k];
        if (!l->text[strspn(l->text, " \t")] || l->text[0] == ';')
            continue;
        if (l->text[0] == '#') {
            if (names && section_name(ld, l) < 0)
                return -1;
            continue;
        }
        if (fn(ld, l, index++) < 0)
            return -1;
    }
    return 0;
}

/* Parse a non-rung embedded file by name; files of unsupported features are ignored. */
int cl_parse_table(cl_load_t *ld, const char *name, const cl_line_t *lines, int count)
{
    static const struct { const char *name; line_fn fn; } tables[] = {
        { "timers.csv", timer_line }, { "monostables.csv", mono_line },
        { "counters.csv", counter_line }, { "timers_iec.csv", timer_iec_line },
        { "arithmetic_expressions.csv", arithm_line }, { "sections.csv", section_line },
        { "symbols.csv", symbol_line }, { "general.txt", general_line },
    };
    for (size_t i = 0; i < sizeof(tables) / sizeof(tables[0]); i++)
        if (strcmp(name, tables[i].name) == 0)
            return each_line(ld, lines, count, tables[i].fn, tables[i].fn == section_line);
    return 0;
}
