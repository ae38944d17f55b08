/* cl_data.h: ClassicLadder PLC data shared by the realtime scan and the project loader. */
#ifndef CL_DATA_H
#define CL_DATA_H

#include <stddef.h>
#include <stdint.h>

#define CL_SHM_KEY 0x436C4144      /* "ClAD"; the instance number is applied by rtapi */
#define CL_MAGIC 0x434C5254u       /* header is valid once this is set */
#define CL_LAYOUT_VERSION 1

#define CL_RUNG_WIDTH 10
#define CL_RUNG_HEIGHT 6
#define CL_LABEL_LEN 12
#define CL_COMMENT_LEN 64
#define CL_SECTION_NAME_LEN 24
#define CL_SYMBOL_VAR_LEN 12
#define CL_SYMBOL_NAME_LEN 24
#define CL_SYMBOL_COMMENT_LEN 48
#define CL_EXPR_MAX_OPS 48
#define CL_CALL_DEPTH 4
#define CL_COUNTER_MAX 9999

/* Element types of a rung cell (ClassicLadder numbering). */
enum {
    ELE_FREE = 0, ELE_INPUT = 1, ELE_INPUT_NOT = 2, ELE_RISING_INPUT = 3,
    ELE_FALLING_INPUT = 4, ELE_CONNECTION = 9, ELE_TIMER = 10, ELE_MONOSTABLE = 11,
    ELE_COUNTER = 12, ELE_TIMER_IEC = 13, ELE_COMPAR = 20, ELE_OUTPUT = 50,
    ELE_OUTPUT_NOT = 51, ELE_OUTPUT_SET = 52, ELE_OUTPUT_RESET = 53, ELE_OUTPUT_JUMP = 54,
    ELE_OUTPUT_CALL = 55, ELE_OUTPUT_OPERATE = 60, ELE_UNUSABLE = 99
};

/* Variable types (ClassicLadder numbering); bits below 200, words from 200. */
enum {
    VAR_MEM_BIT = 0, VAR_TIMER_DONE = 10, VAR_TIMER_RUNNING = 11,
    VAR_MONOSTABLE_RUNNING = 20, VAR_COUNTER_DONE = 25, VAR_COUNTER_EMPTY = 26,
    VAR_COUNTER_FULL = 27, VAR_TIMER_IEC_DONE = 35, VAR_PHYS_INPUT = 50,
    VAR_PHYS_OUTPUT = 60, VAR_ERROR_BIT = 80, VAR_MEM_WORD = 200,
    VAR_TIMER_PRESET = 250, VAR_TIMER_VALUE = 251, VAR_MONOSTABLE_PRESET = 260,
    VAR_MONOSTABLE_VALUE = 261, VAR_COUNTER_PRESET = 270, VAR_COUNTER_VALUE = 271,
    VAR_TIMER_IEC_PRESET = 275, VAR_TIMER_IEC_VALUE = 276, VAR_PHYS_WORD_INPUT = 280,
    VAR_PHYS_WORD_OUTPUT = 290, VAR_PHYS_FLOAT_INPUT = 300, VAR_PHYS_FLOAT_OUTPUT = 310
};

/* Module sizes, in the order of the module parameters. */
enum {
    CL_N_RUNGS, CL_N_BITS, CL_N_WORDS, CL_N_TIMERS, CL_N_MONOSTABLES, CL_N_COUNTERS,
    CL_N_PHYS_IN, CL_N_PHYS_OUT, CL_N_ARITHM, CL_N_SECTIONS, CL_N_SYMBOLS, CL_N_S32_IN,
    CL_N_S32_OUT, CL_N_FLOAT_IN, CL_N_FLOAT_OUT, CL_N_TIMERS_IEC, CL_N_ERROR_BITS,
    CL_N_SIZES
};

/* Arrays of the data segment, each at an offset from the header. */
enum {
    CL_A_RUNGS, CL_A_BITS, CL_A_WORDS, CL_A_TIMERS, CL_A_MONOS, CL_A_COUNTERS,
    CL_A_PHYS_IN, CL_A_PHYS_OUT, CL_A_ARITHM, CL_A_SECTIONS, CL_A_SYMBOLS, CL_A_S32_IN,
    CL_A_S32_OUT, CL_A_FLOAT_IN, CL_A_FLOAT_OUT, CL_A_TIMERS_IEC, CL_A_ERROR_BITS,
    CL_A_COUNT
};

/* One grid cell of a rung. */
typedef struct {
    int16_t type;
    int8_t connected_top;     /* vertical link on the left edge up to the row above */
    int8_t dyn_out;           /* power flowing out on the right after evaluation */
    int8_t dyn_prev;          /* previous variable state (edge contacts) */
    int16_t var_type;
    int32_t var_num;
} cl_cell_t;

/* One rung: grid plus the links of its section chain. */
typedef struct {
    int32_t used, prev, next;
    char label[CL_LABEL_LEN];
    char comment[CL_COMMENT_LEN];
    cl_cell_t cells[CL_RUNG_HEIGHT][CL_RUNG_WIDTH];
} cl_rung_t;

/* Classic timer (%T): enable E, control C, outputs done D and running R. */
typedef struct {
    int32_t base_ms, preset, value, done, running;
    int64_t acc_ns;
} cl_timer_t;

/* Monostable (%M): rising input starts a countdown from preset. */
typedef struct {
    int32_t base_ms, preset, value, running, prev_in;
    int64_t acc_ns;
} cl_mono_t;

/* Counter (%C): reset, preset, up and down inputs; empty, done, full outputs. */
typedef struct {
    int32_t preset, value, empty, done, full, prev_up, prev_down;
} cl_counter_t;

/* IEC timer (%TM): mode 0 TON, 1 TOF, 2 TP. */
typedef struct {
    int32_t base_ms, preset, value, mode, q, prev_in, active;
    int64_t acc_ns;
} cl_timer_iec_t;

/* One instruction of a compiled expression (reverse Polish). */
typedef struct {
    int16_t op;
    int16_t var_type;
    int32_t arg;              /* constant, variable number or function argument count */
} cl_op_t;

/* Compiled arithmetic expression; ops[0..count-1], assignment target for operate. */
typedef struct {
    int32_t count;
    int16_t store_type;       /* -1 when the expression is a comparison */
    int32_t store_num;
    cl_op_t ops[CL_EXPR_MAX_OPS];
} cl_expr_t;

/* Section: a ladder program (main or subroutine SRn) made of a rung chain. */
typedef struct {
    int32_t used, language, sr_number, first_rung, last_rung;
    char name[CL_SECTION_NAME_LEN];
} cl_section_t;

/* Symbol naming a variable (kept for tools; the scan does not use it). */
typedef struct {
    char var[CL_SYMBOL_VAR_LEN];
    char symbol[CL_SYMBOL_NAME_LEN];
    char comment[CL_SYMBOL_COMMENT_LEN];
} cl_symbol_t;

/* Header at the start of the data segment. */
typedef struct {
    uint32_t magic, version;
    int32_t sizes[CL_N_SIZES];
    uint64_t total_size;
    uint64_t offsets[CL_A_COUNT];
    volatile int32_t loading;  /* loader is rewriting the program: scans skip */
    volatile int32_t in_scan;  /* a scan is running */
    volatile int32_t loaded;   /* a project has been loaded */
    volatile uint32_t scans;
} cl_header_t;

/* Pointers into one data segment (or a private copy with the same layout). */
typedef struct {
    cl_header_t *hdr;
    cl_rung_t *rungs;
    int8_t *bits, *phys_in, *phys_out, *error_bits;
    int32_t *words, *s32_in, *s32_out;
    double *float_in, *float_out;
    cl_timer_t *timers;
    cl_mono_t *monos;
    cl_counter_t *counters;
    cl_timer_iec_t *timers_iec;
    cl_expr_t *arithm;
    cl_section_t *sections;
    cl_symbol_t *symbols;
} cl_mem_t;

/* Largest element count of any array (far above every module parameter's maximum). */
#define CL_MAX_ARRAY_SIZE 1000000

size_t cl_layout(cl_header_t *hdr, const int32_t sizes[CL_N_SIZES]);
int cl_layout_valid(const cl_header_t *hdr);
void cl_map(cl_mem_t *m, void *base);
void cl_clear_program(cl_mem_t *m);
void cl_clear_state(cl_mem_t *m);
void cl_copy_program(cl_mem_t *dst, const cl_mem_t *src);

#endif
