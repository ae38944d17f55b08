/* cl_eval.c: evaluates rungs column by column and runs sections, jumps and calls. */
#include "cl_eval.h"
#include "cl_blocks.h"
#include "cl_expr.h"
#include "cl_vars.h"

/* State of one scan. */
typedef struct {
    cl_mem_t *m;
    long period_ns;
    int depth;
} scan_t;

static void run_section(scan_t *s, const cl_section_t *sec);

/* Block size of each element type. */
cl_block_t cl_element_block(int type)
{
    switch (type) {
    case ELE_TIMER: case ELE_MONOSTABLE: case ELE_TIMER_IEC: return (cl_block_t){ 2, 2 };
    case ELE_COUNTER: return (cl_block_t){ 2, 4 };
    case ELE_COMPAR: case ELE_OUTPUT_OPERATE: return (cl_block_t){ 3, 1 };
    default: return (cl_block_t){ 1, 1 };
    }
}

/* Power arriving at the left edge of cell (x, y), through the vertical links there. */
static int state_on_left(const cl_rung_t *r, int x, int y)
{
    int on, py;

    if (x <= 0)
        return 1;
    on = r->cells[y][x - 1].dyn_out;
    for (py = y; py > 0 && r->cells[py][x].connected_top && !on; py--)
        on = r->cells[py - 1][x - 1].dyn_out;
    for (py = y + 1; py < CL_RUNG_HEIGHT && r->cells[py][x].connected_top && !on; py++)
        on = r->cells[py][x - 1].dyn_out;
    return on;
}

/* Contacts: plain, inverted, rising and falling edge. */
static int eval_contact(scan_t *s, cl_cell_t *c, int left)
{
    int v = cl_var_read(s->m, c->var_type, c->var_num) != 0;
    int prev = c->dyn_prev;

    c->dyn_prev = (int8_t)v;
    switch (c->type) {
    case ELE_INPUT: return left && v;
    case ELE_INPUT_NOT: return left && !v;
    case ELE_RISING_INPUT: return left && v && !prev;
    default: return left && !v && prev;
    }
}

/* Subroutine section with number sr, or NULL. */
static const cl_section_t *find_subroutine(const cl_mem_t *m, int sr)
{
    for (int i = 0; i < m->hdr->sizes[CL_N_SECTIONS]; i++)
        if (m->sections[i].used && m->sections[i].sr_number == sr)
            return &m->sections[i];
    return NULL;
}

/* Coils; a jump returns its target rung through *jump. */
static void eval_coil(scan_t *s, cl_cell_t *c, int left, int *jump)
{
    switch (c->type) {
    case ELE_OUTPUT: cl_var_write(s->m, c->var_type, c->var_num, left); break;
    case ELE_OUTPUT_NOT: cl_var_write(s->m, c->var_type, c->var_num, !left); break;
    case ELE_OUTPUT_SET: if (left) cl_var_write(s->m, c->var_type, c->var_num, 1); break;
    case ELE_OUTPUT_RESET: if (left) cl_var_write(s->m, c->var_type, c->var_num, 0); break;
    case ELE_OUTPUT_JUMP: if (left && *jump < 0) *jump = c->var_num; break;
    case ELE_OUTPUT_CALL:
        if (left && s->depth < CL_CALL_DEPTH) {
            const cl_section_t *sub = find_subroutine(s->m, c->var_num);
            s->depth++;
            if (sub)
                run_section(s, sub);
            s->depth--;
        }
        break;
    default:
        if (left)
            cl_expr_operate(s->m, &s->m->arithm[c->var_num]);
        break;
    }
    c->dyn_out = (int8_t)left;
}

/* Function blocks; inputs from the left of the block's left column, outputs on the right. */
static void eval_block(scan_t *s, cl_rung_t *r, int x, int y)
{
    cl_cell_t *c = &r->cells[y][x];
    cl_mem_t *m = s->m;
    int in0 = state_on_left(r, x - 1, y);

    if (c->type == ELE_TIMER) {
        cl_timer_t *t = &m->timers[c->var_num];
        cl_timer_step(t, in0, state_on_left(r, x - 1, y + 1), s->period_ns);
        c->dyn_out = (int8_t)t->done;
        r->cells[y + 1][x].dyn_out = (int8_t)t->running;
    } else if (c->type == ELE_MONOSTABLE) {
        cl_mono_step(&m->monos[c->var_num], in0, s->period_ns);
        c->dyn_out = (int8_t)m->monos[c->var_num].running;
    } else if (c->type == ELE_TIMER_IEC) {
        cl_timer_iec_step(&m->timers_iec[c->var_num], in0, s->period_ns);
        c->dyn_out = (int8_t)m->timers_iec[c->var_num].q;
    } else {
        cl_counter_t *k = &m->counters[c->var_num];
        cl_counter_step(k, in0, state_on_left(r, x - 1, y + 1),
                        state_on_left(r, x - 1, y + 2), state_on_left(r, x - 1, y + 3));
        c->dyn_out = (int8_t)k->empty;
        r->cells[y + 1][x].dyn_out = (int8_t)k->done;
        r->cells[y + 2][x].dyn_out = (int8_t)k->full;
    }
}

/* Evaluate one cell; a jump coil reports its target through *jump. */
static void eval_cell(scan_t *s, cl_rung_t *r, int x, int y, int *jump)
{
    cl_cell_t *c = &r->cells[y][x];

    switch (c->type) {
    case ELE_FREE: c->dyn_out = 0; break;
    case ELE_UNUSABLE: break;
    case ELE_CONNECTION: c->dyn_out = (int8_t)state_on_left(r, x, y); break;
    case ELE_INPUT: case ELE_INPUT_NOT: case ELE_RISING_INPUT: case ELE_FALLING_INPUT:
        c->dyn_out = (int8_t)eval_contact(s, c, state_on_left(r, x, y));
        break;
    case ELE_COMPAR:
        c->dyn_out = state_on_left(r, x - 2, y) &&
                     cl_expr_value(s->m, &s->m->arithm[c->var_num]) != 0;
        break;
    case ELE_TIMER: case ELE_MONOSTABLE: case ELE_TIMER_IEC: case ELE_COUNTER:
        eval_block(s, r, x, y);
        break;
    case ELE_OUTPUT_OPERATE:
        eval_coil(s, c, state_on_left(r, x - 2, y), jump);
        break;
    default:
        eval_coil(s, c, state_on_left(r, x, y), jump);
        break;
    }
}

/* Evaluate rung r; returns the rung a jump coil selected, or -1. */
static int eval_rung(scan_t *s, cl_rung_t *r)
{
    int jump = -1;

    for (int y = 0; y < CL_RUNG_HEIGHT; y++)
        for (int x = 0; x < CL_RUNG_WIDTH; x++)
            r->cells[y][x].dyn_out = 0;
    for (int x = 0; x < CL_RUNG_WIDTH; x++)
        for (int y = 0; y < CL_RUNG_HEIGHT; y++)
            eval_cell(s, r, x, y, &jump);
    return jump;
}

/* Run a section's rung chain from its first rung, following jumps (bounded). */
static void run_section(scan_t *s, const cl_section_t *sec)
{
    cl_mem_t *m = s->m;
    int nrungs = m->hdr->sizes[CL_N_RUNGS];
    int budget = 4 * nrungs + 4;
    int rung = sec->first_rung;

    while (rung >= 0 && rung < nrungs && m->rungs[rung].used && budget-- > 0) {
        int jump = eval_rung(s, &m->rungs[rung]);
        if (jump >= 0)
            rung = jump;
        else if (rung == sec->last_rung)
            break;
        else
            rung = m->rungs[rung].next;
    }
}

/* One PLC scan: every main ladder section in order. */
void cl_scan(cl_mem_t *m, long period_ns)
{
    scan_t s = { m, period_ns, 0 };

    for (int i = 0; i < m->hdr->sizes[CL_N_SECTIONS]; i++) {
        const cl_section_t *sec = &m->sections[i];
        if (sec->used && sec->language == 0 && sec->sr_number < 0)
            run_section(&s, sec);
    }
}
