/* cl_check.c: validates a parsed project so the realtime scan can trust every index. */
#include <stdarg.h>
#include <stdio.h>
#include "cl_project.h"
#include "cl_eval.h"
#include "cl_vars.h"

/* Line of row y of rung n in the project file. */
#define ROW_LINE(ld, n, y) ((ld)->row_lines[(n) * CL_RUNG_HEIGHT + (y)])

/* Error at a cell: "rung R, row Y, column X: ..." on the line of that grid row. */
static int __attribute__((format(printf, 5, 6)))
cell_error(cl_load_t *ld, int rung, int y, int x, const char *fmt, ...)
{
    char msg[CL_ERR_LEN / 2];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof(msg), fmt, ap);
    va_end(ap);
    return cl_load_error(ld, ROW_LINE(ld, rung, y), "rung %d, row %d, column %d: %s", rung, y,
                         x, msg);
}

/* Element kinds by type: 1 contact, 2 coil on a bit, 3 other coil, 4 block, 5 expression. */
static int kind_of(int type)
{
    switch (type) {
    case ELE_INPUT: case ELE_INPUT_NOT: case ELE_RISING_INPUT: case ELE_FALLING_INPUT: return 1;
    case ELE_OUTPUT: case ELE_OUTPUT_NOT: case ELE_OUTPUT_SET: case ELE_OUTPUT_RESET: return 2;
    case ELE_OUTPUT_JUMP: case ELE_OUTPUT_CALL: return 3;
    case ELE_TIMER: case ELE_MONOSTABLE: case ELE_COUNTER: case ELE_TIMER_IEC: return 4;
    case ELE_COMPAR: case ELE_OUTPUT_OPERATE: return 5;
    case ELE_FREE: case ELE_CONNECTION: case ELE_UNUSABLE: return 0;
    default: return -1;
    }
}

/* Contact or coil variable: a supported bit variable in range (writable for coils). */
static int check_bit_var(cl_load_t *ld, int rung, int x, int y, const cl_cell_t *c, int coil)
{
    const cl_var_desc_t *d = cl_var_desc(c->var_type);

    if (!d || c->var_type >= VAR_MEM_WORD)
        return cell_error(ld, rung, y, x, "variable type %d is not a supported bit variable",
                          c->var_type);
    if (c->var_num < 0 || c->var_num >= ld->m->hdr->sizes[d->size_index])
        return cell_error(ld, rung, y, x, "%s%d%s out of range (module has %d)", d->prefix,
                          c->var_num, d->suffix, ld->m->hdr->sizes[d->size_index]);
    if (coil && !d->writable)
        return cell_error(ld, rung, y, x, "coil cannot write %s%d%s", d->prefix, c->var_num,
                          d->suffix);
    return 0;
}

/* Number of the block's objects (timers, counters ...) in this module. */
static int block_limit(const cl_mem_t *m, int type)
{
    switch (type) {
    case ELE_TIMER: return m->hdr->sizes[CL_N_TIMERS];
    case ELE_MONOSTABLE: return m->hdr->sizes[CL_N_MONOSTABLES];
    case ELE_COUNTER: return m->hdr->sizes[CL_N_COUNTERS];
    case ELE_TIMER_IEC: return m->hdr->sizes[CL_N_TIMERS_IEC];
    default: return m->hdr->sizes[CL_N_ARITHM];
    }
}

/* Block or expression element: fits the grid, other cells unusable, object in range. */
static int check_block(cl_load_t *ld, const cl_rung_t *r, int rung, int x, int y)
{
    const cl_cell_t *c = &r->cells[y][x];
    cl_block_t b = cl_element_block(c->type);
    const cl_expr_t *e;

    if (x - (b.width - 1) < 0 || y + b.height > CL_RUNG_HEIGHT)
        return cell_error(ld, rung, y, x, "element type %d needs %dx%d cells", c->type, b.width,
                          b.height);
    for (int dy = 0; dy < b.height; dy++)
        for (int dx = 0; dx < b.width; dx++)
            if ((dx || dy) && r->cells[y + dy][x - dx].type != ELE_UNUSABLE)
                return cell_error(ld, rung, y + dy, x - dx, "cell of element type %d must be "
                                  "unusable (99)", c->type);
    if (c->var_num < 0 || c->var_num >= block_limit(ld->m, c->type))
        return cell_error(ld, rung, y, x, "element number %d out of range (module has %d)",
                          c->var_num, block_limit(ld->m, c->type));
    if (kind_of(c->type) != 5)
        return 0;
    e = &ld->m->arithm[c->var_num];
    if (e->count == 0)
        return cell_error(ld, rung, y, x, "expression %d is not defined", c->var_num);
    if ((c->type == ELE_COMPAR) != (e->store_type < 0))
        return cell_error(ld, rung, y, x, "expression %d %s", c->var_num,
                          c->type == ELE_COMPAR ? "is an assignment, not a comparison"
                                                : "has no 'VARIABLE :=' assignment");
    return 0;
}

/* Jump target must be a used rung; call target an existing subroutine section. */
static int check_flow(cl_load_t *ld, int rung, int x, int y, const cl_cell_t *c)
{
    const cl_mem_t *m = ld->m;

    if (c->type == ELE_OUTPUT_JUMP) {
        if (c->var_num < 0 || c->var_num >= m->hdr->sizes[CL_N_RUNGS] ||
            !m->rungs[c->var_num].used)
            return cell_error(ld, rung, y, x, "jump to undefined rung %d", c->var_num);
        return 0;
    }
    for (int i = 0; i < m->hdr->sizes[CL_N_SECTIONS]; i++)
        if (m->sections[i].used && m->sections[i].sr_number == c->var_num && c->var_num >= 0)
            return 0;
    return cell_error(ld, rung, y, x, "call of undefined subroutine SR%d", c->var_num);
}

/* Check every cell of rung n. */
static int check_rung(cl_load_t *ld, int n)
{
    const cl_rung_t *r = &ld->m->rungs[n];

    for (int y = 0; y < CL_RUNG_HEIGHT; y++)
        for (int x = 0; x < CL_RUNG_WIDTH; x++) {
            const cl_cell_t *c = &r->cells[y][x];
            int k = kind_of(c->type), rc = 0;
            if (k < 0)
                rc = cell_error(ld, n, y, x, "unknown element type %d", c->type);
            else if (k == 1 || k == 2)
                rc = check_bit_var(ld, n, x, y, c, k == 2);
            else if (k == 3)
                rc = check_flow(ld, n, x, y, c);
            else if (k >= 4)
                rc = check_block(ld, r, n, x, y);
            if (rc < 0)
                return -1;
        }
    return 0;
}

/* A rung link must be -1 or a used rung. */
static int link_ok(const cl_mem_t *m, int rung)
{
    return rung == -1 || (rung >= 0 && rung < m->hdr->sizes[CL_N_RUNGS] && m->rungs[rung].used);
}

/* Whole project: rungs, their links, sections. */
int cl_check_project(cl_load_t *ld)
{
    const cl_mem_t *m = ld->m;

    for (int n = 0; n < m->hdr->sizes[CL_N_RUNGS]; n++) {
        if (!m->rungs[n].used)
            continue;
        if (!link_ok(m, m->rungs[n].next))
            return cl_load_error(ld, ld->rung_lines[n], "rung %d: #NEXTRUNG=%d is not a defined "
                                 "rung", n, m->rungs[n].next);
        if (check_rung(ld, n) < 0)
            return -1;
    }
    for (int i = 0; i < m->hdr->sizes[CL_N_SECTIONS]; i++) {
        const cl_section_t *s = &m->sections[i];
        if (s->used && (s->first_rung < 0 || !link_ok(m, s->first_rung)))
            return cl_load_error(ld, ld->section_lines[i], "section %d: first rung %d is not a "
                                 "defined rung", i, s->first_rung);
    }
    return 0;
}
