/* cl_layout.c: places the PLC arrays in one data segment and resets program or state. */
#include <string.h>
#include "cl_data.h"

/* Element size of each array, in CL_A_* order. */
static const size_t elem_size[CL_A_COUNT] = {
    sizeof(cl_rung_t), 1, sizeof(int32_t), sizeof(cl_timer_t), sizeof(cl_mono_t),
    sizeof(cl_counter_t), 1, 1, sizeof(cl_expr_t), sizeof(cl_section_t),
    sizeof(cl_symbol_t), sizeof(int32_t), sizeof(int32_t), sizeof(double), sizeof(double),
    sizeof(cl_timer_iec_t), 1
};

/* Fill the header's sizes and offsets; returns the total segment size in bytes. */
size_t cl_layout(cl_header_t *hdr, const int32_t sizes[CL_N_SIZES])
{
    size_t pos = (sizeof(*hdr) + 15) & ~(size_t)15;

    memset(hdr, 0, sizeof(*hdr));
    hdr->version = CL_LAYOUT_VERSION;
    for (int i = 0; i < CL_N_SIZES; i++)
        hdr->sizes[i] = sizes[i];
    for (int a = 0; a < CL_A_COUNT; a++) {
        hdr->offsets[a] = pos;
        pos += ((elem_size[a] * (size_t)sizes[a]) + 15) & ~(size_t)15;
    }
    hdr->total_size = pos;
    return pos;
}

/* True when hdr's offsets and total size are the layout of its sizes (a header read from shared
   memory is checked before its offsets are used to write anywhere). */
int cl_layout_valid(const cl_header_t *hdr)
{
    cl_header_t expect;

    for (int i = 0; i < CL_N_SIZES; i++)
        if (hdr->sizes[i] < 0 || hdr->sizes[i] > CL_MAX_ARRAY_SIZE)
            return 0;
    cl_layout(&expect, hdr->sizes);
    return expect.total_size == hdr->total_size &&
           memcmp(expect.offsets, hdr->offsets, sizeof(expect.offsets)) == 0;
}

/* Point m's arrays into the segment at base, whose header is already laid out. */
void cl_map(cl_mem_t *m, void *base)
{
    char *b = base;
    cl_header_t *h = base;

    m->hdr = h;
    m->rungs = (cl_rung_t *)(b + h->offsets[CL_A_RUNGS]);
    m->bits = (int8_t *)(b + h->offsets[CL_A_BITS]);
    m->words = (int32_t *)(b + h->offsets[CL_A_WORDS]);
    m->timers = (cl_timer_t *)(b + h->offsets[CL_A_TIMERS]);
    m->monos = (cl_mono_t *)(b + h->offsets[CL_A_MONOS]);
    m->counters = (cl_counter_t *)(b + h->offsets[CL_A_COUNTERS]);
    m->phys_in = (int8_t *)(b + h->offsets[CL_A_PHYS_IN]);
    m->phys_out = (int8_t *)(b + h->offsets[CL_A_PHYS_OUT]);
    m->arithm = (cl_expr_t *)(b + h->offsets[CL_A_ARITHM]);
    m->sections = (cl_section_t *)(b + h->offsets[CL_A_SECTIONS]);
    m->symbols = (cl_symbol_t *)(b + h->offsets[CL_A_SYMBOLS]);
    m->s32_in = (int32_t *)(b + h->offsets[CL_A_S32_IN]);
    m->s32_out = (int32_t *)(b + h->offsets[CL_A_S32_OUT]);
    m->float_in = (double *)(b + h->offsets[CL_A_FLOAT_IN]);
    m->float_out = (double *)(b + h->offsets[CL_A_FLOAT_OUT]);
    m->timers_iec = (cl_timer_iec_t *)(b + h->offsets[CL_A_TIMERS_IEC]);
    m->error_bits = (int8_t *)(b + h->offsets[CL_A_ERROR_BITS]);
}

/* Byte range of array a in the segment. */
static void clear_array(cl_mem_t *m, int a)
{
    memset((char *)m->hdr + m->hdr->offsets[a], 0, elem_size[a] * (size_t)m->hdr->sizes[a]);
}

/* Empty program: no rungs, sections, expressions, symbols; default timer settings. */
void cl_clear_program(cl_mem_t *m)
{
    const int32_t *n = m->hdr->sizes;

    clear_array(m, CL_A_RUNGS);
    clear_array(m, CL_A_ARITHM);
    clear_array(m, CL_A_SECTIONS);
    clear_array(m, CL_A_SYMBOLS);
    clear_array(m, CL_A_TIMERS);
    clear_array(m, CL_A_MONOS);
    clear_array(m, CL_A_COUNTERS);
    clear_array(m, CL_A_TIMERS_IEC);
    for (int i = 0; i < n[CL_N_TIMERS]; i++)
        m->timers[i].base_ms = 1000;
    for (int i = 0; i < n[CL_N_MONOSTABLES]; i++)
        m->monos[i].base_ms = 1000;
    for (int i = 0; i < n[CL_N_TIMERS_IEC]; i++)
        m->timers_iec[i].base_ms = 1000;
}

/* Reset the run-time state: memory variables, outputs and element states. */
void cl_clear_state(cl_mem_t *m)
{
    const int32_t *n = m->hdr->sizes;

    clear_array(m, CL_A_BITS);
    clear_array(m, CL_A_WORDS);
    clear_array(m, CL_A_PHYS_OUT);
    clear_array(m, CL_A_S32_OUT);
    clear_array(m, CL_A_FLOAT_OUT);
    clear_array(m, CL_A_ERROR_BITS);
    for (int i = 0; i < n[CL_N_TIMERS]; i++)
        m->timers[i] = (cl_timer_t){ m->timers[i].base_ms, m->timers[i].preset, 0, 0, 0, 0 };
    for (int i = 0; i < n[CL_N_MONOSTABLES]; i++)
        m->monos[i] = (cl_mono_t){ m->monos[i].base_ms, m->monos[i].preset, 0, 0, 0, 0 };
    for (int i = 0; i < n[CL_N_COUNTERS]; i++)
        m->counters[i] = (cl_counter_t){ .preset = m->counters[i].preset };
    for (int i = 0; i < n[CL_N_TIMERS_IEC]; i++) {
        cl_timer_iec_t *t = &m->timers_iec[i];
        *t = (cl_timer_iec_t){ .base_ms = t->base_ms, .preset = t->preset, .mode = t->mode };
    }
}

/* Copy the program arrays (rungs, settings, expressions, sections, symbols) from src to dst. */
void cl_copy_program(cl_mem_t *dst, const cl_mem_t *src)
{
    static const int program[] = {
        CL_A_RUNGS, CL_A_TIMERS, CL_A_MONOS, CL_A_COUNTERS, CL_A_ARITHM, CL_A_SECTIONS,
        CL_A_SYMBOLS, CL_A_TIMERS_IEC
    };
    for (size_t i = 0; i < sizeof(program) / sizeof(program[0]); i++) {
        int a = program[i];
        const char *from = (const char *)src->hdr + src->hdr->offsets[a];
        memcpy((char *)dst->hdr + dst->hdr->offsets[a], from,
               elem_size[a] * (size_t)src->hdr->sizes[a]);
    }
}
