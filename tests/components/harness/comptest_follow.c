/* comptest_follow.c: "follow" rules that play the part of the rest of HAL after each cycle, e.g.
 * motion applying an external offset at once: DEST := SRC * MUL + ADD (MUL a pin name or a number). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fakehal.h"

#define MAX_FOLLOW 16

/* One rule. */
typedef struct {
    fake_item_t *dest, *src, *mul_pin;
    double mul, add;
} follow_t;

static follow_t rules[MAX_FOLLOW];
static int n_rules;

/* A pin or param value as a double. */
static double follow_get(fake_item_t *it)
{
    void *c = fake_cell(it);
    switch (it->type) {
    case HAL_BIT: return *(hal_bit_t *)c ? 1.0 : 0.0;
    case HAL_FLOAT: return *(hal_float_t *)c;
    case HAL_S32: return *(hal_s32_t *)c;
    case HAL_U32: return *(hal_u32_t *)c;
    case HAL_S64: return (double)*(hal_s64_t *)c;
    case HAL_U64: return (double)*(hal_u64_t *)c;
    default: return 0;
    }
}

/* Store a double into a pin or param of any numeric type. */
static void follow_set(fake_item_t *it, double v)
{
    void *c = fake_cell(it);
    switch (it->type) {
    case HAL_BIT: *(hal_bit_t *)c = v != 0; break;
    case HAL_FLOAT: *(hal_float_t *)c = v; break;
    case HAL_S32: *(hal_s32_t *)c = (hal_s32_t)v; break;
    case HAL_U32: *(hal_u32_t *)c = (hal_u32_t)v; break;
    case HAL_S64: *(hal_s64_t *)c = (hal_s64_t)v; break;
    case HAL_U64: *(hal_u64_t *)c = (hal_u64_t)v; break;
    default: break;
    }
}

/* Apply every rule (after a cycle). */
void comptest_follow_apply(void)
{
    for (int i = 0; i < n_rules; i++) {
        follow_t *r = &rules[i];
        double mul = r->mul_pin ? follow_get(r->mul_pin) : r->mul;
        follow_set(r->dest, follow_get(r->src) * mul + r->add);
    }
}

/* Forget every rule (the module they refer to is unloaded). */
void comptest_follow_clear(void)
{
    n_rules = 0;
}

/* follow DEST SRC [MUL [ADD]]: add a rule; "follow" alone removes them all. 1 when argv[0] was it. */
int comptest_follow_dispatch(int argc, char **argv)
{
    if (strcmp(argv[0], "follow")) return 0;
    if (argc == 1) {
        n_rules = 0;
        return 1;
    }
    fake_item_t *d = argc >= 3 ? fake_find(argv[1]) : NULL, *s = argc >= 3 ? fake_find(argv[2]) : NULL;
    if (!d || !s || n_rules >= MAX_FOLLOW) {
        printf("follow: bad rule\n");
        return 1;
    }
    follow_t *r = &rules[n_rules++];
    char *end = NULL;
    r->dest = d;
    r->src = s;
    r->mul = argc > 3 ? strtod(argv[3], &end) : 1.0;
    r->mul_pin = argc > 3 && end == argv[3] ? fake_find(argv[3]) : NULL;
    r->add = argc > 4 ? strtod(argv[4], NULL) : 0.0;
    return 1;
}
