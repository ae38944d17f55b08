/* cl_vars.c: PLC variable access by ClassicLadder type number, and %-name parsing. */
#include <string.h>
#include "cl_vars.h"

/* Every supported variable type; longer prefixes first so "%TM" wins over "%T". */
static const cl_var_desc_t var_table[] = {
    { VAR_TIMER_IEC_DONE, "%TM", ".Q", CL_N_TIMERS_IEC, 0 },
    { VAR_TIMER_IEC_PRESET, "%TM", ".P", CL_N_TIMERS_IEC, 1 },
    { VAR_TIMER_IEC_VALUE, "%TM", ".V", CL_N_TIMERS_IEC, 0 },
    { VAR_PHYS_WORD_INPUT, "%IW", "", CL_N_S32_IN, 0 },
    { VAR_PHYS_WORD_OUTPUT, "%QW", "", CL_N_S32_OUT, 1 },
    { VAR_PHYS_FLOAT_INPUT, "%IF", "", CL_N_FLOAT_IN, 0 },
    { VAR_PHYS_FLOAT_OUTPUT, "%QF", "", CL_N_FLOAT_OUT, 1 },
    { VAR_MEM_BIT, "%B", "", CL_N_BITS, 1 },
    { VAR_MEM_WORD, "%W", "", CL_N_WORDS, 1 },
    { VAR_PHYS_INPUT, "%I", "", CL_N_PHYS_IN, 0 },
    { VAR_PHYS_OUTPUT, "%Q", "", CL_N_PHYS_OUT, 1 },
    { VAR_ERROR_BIT, "%E", "", CL_N_ERROR_BITS, 1 },
    { VAR_TIMER_DONE, "%T", ".D", CL_N_TIMERS, 0 },
    { VAR_TIMER_RUNNING, "%T", ".R", CL_N_TIMERS, 0 },
    { VAR_TIMER_PRESET, "%T", ".P", CL_N_TIMERS, 1 },
    { VAR_TIMER_VALUE, "%T", ".V", CL_N_TIMERS, 0 },
    { VAR_MONOSTABLE_RUNNING, "%M", ".R", CL_N_MONOSTABLES, 0 },
    { VAR_MONOSTABLE_PRESET, "%M", ".P", CL_N_MONOSTABLES, 1 },
    { VAR_MONOSTABLE_VALUE, "%M", ".V", CL_N_MONOSTABLES, 0 },
    { VAR_COUNTER_DONE, "%C", ".D", CL_N_COUNTERS, 0 },
    { VAR_COUNTER_EMPTY, "%C", ".E", CL_N_COUNTERS, 0 },
    { VAR_COUNTER_FULL, "%C", ".F", CL_N_COUNTERS, 0 },
    { VAR_COUNTER_PRESET, "%C", ".P", CL_N_COUNTERS, 1 },
    { VAR_COUNTER_VALUE, "%C", ".V", CL_N_COUNTERS, 1 },
};
#define VAR_TABLE_LEN ((int)(sizeof(var_table) / sizeof(var_table[0])))

/* Descriptor of a variable type, or NULL when unsupported. */
const cl_var_desc_t *cl_var_desc(int type)
{
    for (int i = 0; i < VAR_TABLE_LEN; i++)
        if (var_table[i].type == type)
            return &var_table[i];
    return NULL;
}

/* Number of variables of a type in this module, 0 when unsupported. */
int cl_var_count(const cl_mem_t *m, int type)
{
    const cl_var_desc_t *d = cl_var_desc(type);
    return d ? m->hdr->sizes[d->size_index] : 0;
}

/* Round a float input to the integer the expressions work with. */
static int32_t float_to_int(double x)
{
    if (x >= 2147483647.0) return 2147483647;
    if (x <= -2147483648.0) return (int32_t)-2147483647 - 1;
    return (int32_t)x;
}

/* Value of a timer, monostable or counter field. */
static int32_t read_block(const cl_mem_t *m, int type, int n)
{
    switch (type) {
    case VAR_TIMER_DONE: return m->timers[n].done;
    case VAR_TIMER_RUNNING: return m->timers[n].running;
    case VAR_TIMER_PRESET: return m->timers[n].preset;
    case VAR_TIMER_VALUE: return m->timers[n].value;
    case VAR_MONOSTABLE_RUNNING: return m->monos[n].running;
    case VAR_MONOSTABLE_PRESET: return m->monos[n].preset;
    case VAR_MONOSTABLE_VALUE: return m->monos[n].value;
    case VAR_COUNTER_DONE: return m->counters[n].done;
    case VAR_COUNTER_EMPTY: return m->counters[n].empty;
    case VAR_COUNTER_FULL: return m->counters[n].full;
    case VAR_COUNTER_PRESET: return m->counters[n].preset;
    case VAR_COUNTER_VALUE: return m->counters[n].value;
    case VAR_TIMER_IEC_DONE: return m->timers_iec[n].q;
    case VAR_TIMER_IEC_PRESET: return m->timers_iec[n].preset;
    case VAR_TIMER_IEC_VALUE: return m->timers_iec[n].value;
    default: return 0;
    }
}

/* Value of variable type/num; 0 when out of range. */
int32_t cl_var_read(const cl_mem_t *m, int type, int num)
{
    if (num < 0 || num >= cl_var_count(m, type))
        return 0;
    switch (type) {
    case VAR_MEM_BIT: return m->bits[num];
    case VAR_MEM_WORD: return m->words[num];
    case VAR_PHYS_INPUT: return m->phys_in[num];
    case VAR_PHYS_OUTPUT: return m->phys_out[num];
    case VAR_ERROR_BIT: return m->error_bits[num];
    case VAR_PHYS_WORD_INPUT: return m->s32_in[num];
    case VAR_PHYS_WORD_OUTPUT: return m->s32_out[num];
    case VAR_PHYS_FLOAT_INPUT: return float_to_int(m->float_in[num]);
    case VAR_PHYS_FLOAT_OUTPUT: return float_to_int(m->float_out[num]);
    default: return read_block(m, type, num);
    }
}

/* Store a value into a writable variable; bits store value != 0. */
void cl_var_write(cl_mem_t *m, int type, int num, int32_t value)
{
    if (num < 0 || num >= cl_var_count(m, type))
        return;
    switch (type) {
    case VAR_MEM_BIT: m->bits[num] = value != 0; break;
    case VAR_PHYS_OUTPUT: m->phys_out[num] = value != 0; break;
    case VAR_ERROR_BIT: m->error_bits[num] = value != 0; break;
    case VAR_MEM_WORD: m->words[num] = value; break;
    case VAR_PHYS_WORD_OUTPUT: m->s32_out[num] = value; break;
    case VAR_PHYS_FLOAT_OUTPUT: m->float_out[num] = value; break;
    case VAR_TIMER_PRESET: m->timers[num].preset = value; break;
    case VAR_MONOSTABLE_PRESET: m->monos[num].preset = value; break;
    case VAR_COUNTER_PRESET: m->counters[num].preset = value; break;
    case VAR_COUNTER_VALUE: m->counters[num].value = value; break;
    case VAR_TIMER_IEC_PRESET: m->timers_iec[num].preset = value; break;
    default: break;
    }
}

/* Parse "%W12" / "%T3.D" at text; returns characters used (0 if none) and the type/num. */
int cl_var_parse(const char *text, int *type, int *num)
{
    for (int i = 0; i < VAR_TABLE_LEN; i++) {
        const cl_var_desc_t *d = &var_table[i];
        size_t pl = strlen(d->prefix), sl = strlen(d->suffix);
        const char *p = text + pl;
        long n = 0;

        if (strncmp(text, d->prefix, pl) != 0 || *p < '0' || *p > '9')
            continue;
        while (*p >= '0' && *p <= '9' && n < 1000000)
            n = n * 10 + (*p++ - '0');
        if (strncmp(p, d->suffix, sl) != 0)
            continue;
        if (sl == 0 && *p == '.')
            continue;
        *type = d->type;
        *num = (int)n;
        return (int)(p + sl - text);
    }
    return 0;
}
