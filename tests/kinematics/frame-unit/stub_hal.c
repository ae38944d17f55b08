/* stub_hal.c: the few HAL/RTAPI calls the kinematics frame makes, printing what they are asked. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "hal.h"
#include "stub_hal.h"

const char *stub_fail_pin;  /* a pin name hal_pin_float_newf refuses with -EEXIST */

/* Print a message the way the log would show it. */
void rtapi_print_msg(msg_level_t level, const char *fmt, ...)
{
    va_list ap;
    printf("msg %d: ", (int)level);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/* Component creation: always id 7. */
/* rtapi_print: printed as it is. */
void rtapi_print(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

int hal_init(const char *name)
{
    printf("hal_init %s\n", name);
    return 7;
}

/* Report the ready call. */
int hal_ready(int comp_id)
{
    printf("hal_ready %d\n", comp_id);
    return 0;
}

/* Report the removal. */
int hal_exit(int comp_id)
{
    printf("hal_exit %d\n", comp_id);
    return 0;
}

/* Zeroed memory from a static arena, never freed (HAL memory lives as long as the test). */
void *hal_malloc(long int size)
{
    static _Alignas(16) unsigned char arena[16384];
    static size_t used;
    size_t n = ((size_t)size + 15) & ~(size_t)15;
    if (size < 0 || n > sizeof(arena) - used)
        return NULL;
    used += n;
    return arena + used - n;
}

/* Make a float pin, or refuse the name in stub_fail_pin. */
int hal_pin_float_newf(hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id,
                       const char *fmt, ...)
{
    char name[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(name, sizeof(name), fmt, ap);
    va_end(ap);
    printf("pin %s dir %d comp %d\n", name, (int)dir, comp_id);
    if (stub_fail_pin && !strcmp(stub_fail_pin, name))
        return -EEXIST;
    *data_ptr_addr = calloc(1, sizeof(**data_ptr_addr));
    return 0;
}
