/* hal_core_arena.c: unit test of the arena size setting ($OPENEMC_HAL_SIZE) and running out of HAL memory. */
#include "hal.h"
#include <stdio.h>

/* Report the arena size; unless 'total-only' is given, fill it with pins. */
int main(int argc, char **argv)
{
    hal_stats_t st;
    hal_float_t **cell;
    int id, i, rc = 0;

    setvbuf(stdout, NULL, _IONBF, 0);
    id = hal_init("arena");
    if (id < 0)
        return 1;
    hal_statistics(&st);
    printf("total %ld\n", st.mem_total);
    if (argc > 1 && argv[1][0] == 't')
        return hal_exit(id) < 0;
    printf("hal_malloc(total) is NULL: %d\n", hal_malloc(st.mem_total) == NULL);
    for (i = 0; rc == 0; i++) {
        cell = hal_malloc(sizeof(*cell));
        rc = cell ? hal_pin_float_newf(HAL_IN, cell, id, "arena.%d", i) : -ENOMEM;
    }
    hal_statistics(&st);
    printf("pins before running out: %s, last rc %d (%s), used <= total: %d\n",
           i > 100 ? "more than 100" : "too few", rc, hal_strerror(rc), st.mem_used <= st.mem_total);
    hal_exit(id);
    return 0;
}
