/* fakehal.c: minimal single-process HAL and RTAPI used to unit-test component modules. */
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fakehal.h"

#define FAKE_MAX_ITEMS 4096

static fake_item_t items[FAKE_MAX_ITEMS];
static int n_items;
static int comp_ready, comp_exited, next_id = 10;

/* Look up a registered item by name. */
fake_item_t *fake_find(const char *name)
{
    for (int i = 0; i < n_items; i++)
        if (strcmp(items[i].name, name) == 0 && items[i].kind != FAKE_FUNCT)
            return &items[i];
    for (int i = 0; i < n_items; i++)
        if (strcmp(items[i].name, name) == 0)
            return &items[i];
    return NULL;
}

/* Count of registered items. */
int fake_count(void) { return n_items; }

/* Registered item number i. */
fake_item_t *fake_item(int i) { return &items[i]; }

/* Order items by kind then name. */
static int item_cmp(const void *a, const void *b)
{
    const fake_item_t *x = a, *y = b;
    if (x->kind != y->kind)
        return (int)x->kind - (int)y->kind;
    return strcmp(x->name, y->name);
}

/* Sort the registry (pointers held by components stay valid: cells are separate). */
void fake_sort(void) { qsort(items, n_items, sizeof(items[0]), item_cmp); }

/* The value cell of a pin (through the component's pointer) or param. */
void *fake_cell(fake_item_t *it)
{
    return it->kind == FAKE_PIN ? *it->pin_ptr : it->data;
}

/* Ready flag of the component. */
int fake_ready(void) { return comp_ready; }

/* Whether hal_exit was called. */
int fake_exited(void) { return comp_exited; }

/* A module is about to be loaded: nothing is ready or exited yet. */
void fake_new_load(void)
{
    comp_ready = 0;
    comp_exited = 0;
}

/* Register a new item; returns it or NULL on duplicates/overflow. */
static fake_item_t *add_item(const char *name, fake_kind_t kind, int comp_id)
{
    if (strlen(name) > HAL_NAME_LEN) {
        printf("fakehal: name too long '%s'\n", name);
        return NULL;
    }
    for (int i = 0; i < n_items; i++)
        if (items[i].kind == kind && strcmp(items[i].name, name) == 0) {
            printf("fakehal: duplicate name '%s'\n", name);
            return NULL;
        }
    if (n_items >= FAKE_MAX_ITEMS)
        return NULL;
    fake_item_t *it = &items[n_items++];
    memset(it, 0, sizeof(*it));
    strcpy(it->name, name);
    it->kind = kind;
    it->comp_id = comp_id;
    return it;
}

/* TRUE when [p, p + n) lies in one hal_malloc block (real HAL refuses pin and param storage elsewhere). */
static int in_hal_memory(const void *p, size_t n);

/* The real HAL's refusal of storage outside HAL memory. */
static int outside_hal_memory(const char *name, const void *p, size_t n)
{
    if (in_hal_memory(p, n))
        return 0;
    printf("fakehal: '%s': data address not in HAL memory\n", name);
    return 1;
}

/* Create a pin whose pointer lives at ptr. */
static int new_pin(hal_type_t t, int dir, void **ptr, int id, const char *fmt, va_list ap)
{
    char name[256];
    vsnprintf(name, sizeof(name), fmt, ap);
    if (outside_hal_memory(name, ptr, sizeof(*ptr)))
        return -22;
    fake_item_t *it = add_item(name, FAKE_PIN, id);
    if (!it)
        return -22;
    it->type = t;
    it->dir = dir;
    it->pin_ptr = ptr;
    it->data = calloc(1, 8);
    *ptr = it->data;
    return 0;
}

/* Create a param stored at data. */
static int new_param(hal_type_t t, int dir, void *data, int id, const char *fmt, va_list ap)
{
    char name[256];
    vsnprintf(name, sizeof(name), fmt, ap);
    if (outside_hal_memory(name, data, 1))
        return -22;
    fake_item_t *it = add_item(name, FAKE_PARAM, id);
    if (!it)
        return -22;
    it->type = t;
    it->dir = dir;
    it->data = data;
    return 0;
}

#define FAKE_PIN_NEWF(tn, T, ctype) \
    int hal_pin_##tn##_newf(hal_pin_dir_t dir, ctype **p, int id, const char *fmt, ...) \
    { \
        va_list ap; va_start(ap, fmt); \
        int r = new_pin(T, dir, (void **)p, id, fmt, ap); \
        va_end(ap); return r; \
    }
#define FAKE_PARAM_NEWF(tn, T, ctype) \
    int hal_param_##tn##_newf(hal_param_dir_t dir, ctype *p, int id, const char *fmt, ...) \
    { \
        va_list ap; va_start(ap, fmt); \
        int r = new_param(T, dir, (void *)p, id, fmt, ap); \
        va_end(ap); return r; \
    }

/* hal_pin_<type>_new(name, dir, ptr, id): the plain-name forms. */
#define FAKE_PIN_NEW(tn, T, ctype) \
    int hal_pin_##tn##_new(const char *name, hal_pin_dir_t dir, ctype **p, int id) \
    { \
        return hal_pin_new(name, T, dir, (void **)p, id); \
    }

FAKE_PIN_NEWF(bit, HAL_BIT, hal_bit_t)
FAKE_PIN_NEWF(float, HAL_FLOAT, hal_float_t)
FAKE_PIN_NEWF(s32, HAL_S32, hal_s32_t)
FAKE_PIN_NEWF(u32, HAL_U32, hal_u32_t)
FAKE_PIN_NEWF(s64, HAL_S64, hal_s64_t)
FAKE_PIN_NEWF(u64, HAL_U64, hal_u64_t)
FAKE_PIN_NEWF(port, HAL_PORT, hal_port_t)
FAKE_PARAM_NEWF(bit, HAL_BIT, hal_bit_t)
FAKE_PARAM_NEWF(float, HAL_FLOAT, hal_float_t)
FAKE_PARAM_NEWF(s32, HAL_S32, hal_s32_t)
FAKE_PARAM_NEWF(u32, HAL_U32, hal_u32_t)
FAKE_PARAM_NEWF(s64, HAL_S64, hal_s64_t)
FAKE_PARAM_NEWF(u64, HAL_U64, hal_u64_t)
FAKE_PIN_NEW(bit, HAL_BIT, hal_bit_t)
FAKE_PIN_NEW(float, HAL_FLOAT, hal_float_t)
FAKE_PIN_NEW(s32, HAL_S32, hal_s32_t)
FAKE_PIN_NEW(u32, HAL_U32, hal_u32_t)
FAKE_PIN_NEW(s64, HAL_S64, hal_s64_t)
FAKE_PIN_NEW(u64, HAL_U64, hal_u64_t)

/* Register a funct plus its .time pin and .tmax/.tmax-increased params. */
int hal_export_funct(const char *name, void (*funct)(void *, long), void *arg,
                     int uses_fp, int reentrant, int comp_id)
{
    (void)uses_fp; (void)reentrant;
    fake_item_t *it = add_item(name, FAKE_FUNCT, comp_id);
    if (!it)
        return -22;
    it->funct = funct;
    it->arg = arg;
    return 0;
}

/* printf-style funct export. */
int hal_export_functf(void (*funct)(void *, long), void *arg, int uses_fp,
                      int reentrant, int comp_id, const char *fmt, ...)
{
    char name[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(name, sizeof(name), fmt, ap);
    va_end(ap);
    return hal_export_funct(name, funct, arg, uses_fp, reentrant, comp_id);
}

/* Component creation: one id per call. */
int hal_init(const char *name)
{
    printf("hal_init %s\n", name);
    return next_id++;
}

/* Mark the component ready. */
int hal_ready(int comp_id) { (void)comp_id; comp_ready = 1; return 0; }

/* Mark the component not ready again (kinematics that add pins at their first type query). */
int hal_unready(int comp_id) { (void)comp_id; comp_ready = 0; return 0; }

/* Record that the component was removed and drop its pins, params and functs. */
int hal_exit(int comp_id)
{
    int kept = 0;
    for (int i = 0; i < n_items; i++) {
        if (items[i].comp_id != comp_id) {
            items[kept++] = items[i];
            continue;
        }
        if (items[i].kind == FAKE_PIN)
            free(items[i].data);
    }
    n_items = kept;
    comp_exited = 1;
    return 0;
}

/* One hal_malloc block: kept on a list, as HAL memory lives until HAL goes away. */
typedef struct fake_block {
    struct fake_block *next;
    size_t size;
    max_align_t data[];
} fake_block_t;

static fake_block_t *blocks;

/* Zeroed memory owned by the fake HAL until fake_free_memory. */
void *hal_malloc(long int size)
{
    fake_block_t *b = size < 0 ? NULL : calloc(1, sizeof(*b) + (size_t)size);
    if (!b)
        return NULL;
    b->next = blocks;
    b->size = (size_t)size;
    blocks = b;
    return b->data;
}

static int in_hal_memory(const void *p, size_t n)
{
    const char *c = p;
    for (fake_block_t *b = blocks; b; b = b->next)
        if (c >= (const char *)b->data && c + n <= (const char *)b->data + b->size)
            return 1;
    return 0;
}

/* Free every hal_malloc block (when the fake HAL shuts down). */
void fake_free_memory(void)
{
    while (blocks) {
        fake_block_t *next = blocks->next;
        free(blocks);
        blocks = next;
    }
}

/* Constructors are accepted and ignored. */
int hal_set_constructor(int comp_id, hal_constructor_t make)
{
    (void)comp_id; (void)make;
    return 0;
}

/* Messages go to stdout so tests can compare them. */
/* The message level: errors only unless a component raises it (plasmac's debug-print). */
static int fake_msg_level = RTAPI_MSG_ERR;

int rtapi_set_msg_level(int level)
{
    fake_msg_level = level;
    return 0;
}

int rtapi_get_msg_level(void)
{
    return fake_msg_level;
}

void rtapi_print_msg(msg_level_t level, const char *fmt, ...)
{
    va_list ap;
    if ((int)level > fake_msg_level)
        return;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/* Plain print to stdout. */
void rtapi_print(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/* snprintf wrapper. */
int rtapi_snprintf(char *buf, unsigned long size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int r = vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return r;
}

/* vsnprintf wrapper. */
int rtapi_vsnprintf(char *buf, unsigned long size, const char *fmt, va_list ap)
{
    return vsnprintf(buf, size, fmt, ap);
}

/* A deterministic clock: advanced only by comptest's 'run'. */
long long fake_clock_ns;
long long rtapi_get_time(void) { return fake_clock_ns; }

/* strlcpy for modules. */
size_t rtapi_strlcpy(char *dst, const char *src, size_t size)
{
    size_t n = strlen(src);
    if (size) {
        size_t c = n < size - 1 ? n : size - 1;
        memcpy(dst, src, c);
        dst[c] = '\0';
    }
    return n;
}

/* Generic pin creation by name and type. */
int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id)
{
    if (outside_hal_memory(name, data_ptr_addr, sizeof(*data_ptr_addr)))
        return -22;
    fake_item_t *it = add_item(name, FAKE_PIN, comp_id);
    if (!it)
        return -22;
    it->type = type;
    it->dir = dir;
    it->pin_ptr = data_ptr_addr;
    it->data = calloc(1, 8);
    *data_ptr_addr = it->data;
    return 0;
}
