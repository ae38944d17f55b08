/* hal_pin_typed.c: the typed pin constructors (classic, printf-style and new API). */
#include "hal_internal.h"
#include <stdarg.h>

/* Classic constructors: caller supplies the pointer cell. */
#define HAL_PIN_NEW(T, TYPE, CT)                                                       \
    int hal_pin_##T##_new(const char *name, hal_pin_dir_t dir, CT **data_ptr_addr,     \
                          int comp_id)                                                 \
    {                                                                                  \
        return hal_pin_new(name, TYPE, dir, (void **)data_ptr_addr, comp_id);          \
    }                                                                                  \
    int hal_pin_##T##_newf(hal_pin_dir_t dir, CT **data_ptr_addr, int comp_id,         \
                           const char *fmt, ...)                                       \
    {                                                                                  \
        va_list ap;                                                                    \
        int rc;                                                                        \
        va_start(ap, fmt);                                                             \
        rc = halpr_item_new_va(1, TYPE, dir, (void *)data_ptr_addr, comp_id, fmt, ap); \
        va_end(ap);                                                                    \
        return rc;                                                                     \
    }

HAL_PIN_NEW(bit, HAL_BIT, hal_bit_t)
HAL_PIN_NEW(float, HAL_FLOAT, hal_float_t)
HAL_PIN_NEW(u32, HAL_U32, hal_u32_t)
HAL_PIN_NEW(s32, HAL_S32, hal_s32_t)
HAL_PIN_NEW(u64, HAL_U64, hal_u64_t)
HAL_PIN_NEW(s64, HAL_S64, hal_s64_t)
HAL_PIN_NEW(port, HAL_PORT, hal_port_t)

/* New API constructors: start value dflt. */
#define HAL_PIN_NEW_REF(T, TYPE, CT, DT)                                       \
    int hal_pin_new_##T(int comp_id, hal_pin_dir_t dir, CT ***ref, DT dflt,    \
                        const char *fmt, ...)                                  \
    {                                                                          \
        va_list ap;                                                            \
        int rc;                                                                \
        va_start(ap, fmt);                                                     \
        rc = halpr_item_new_ref(1, TYPE, dir, (void **)ref, comp_id, fmt, ap); \
        va_end(ap);                                                            \
        if (rc == 0)                                                           \
            ***ref = dflt;                                                     \
        return rc;                                                             \
    }

HAL_PIN_NEW_REF(bool, HAL_BIT, hal_bit_t, bool)
HAL_PIN_NEW_REF(si32, HAL_S32, hal_s32_t, int32_t)
HAL_PIN_NEW_REF(ui32, HAL_U32, hal_u32_t, uint32_t)
HAL_PIN_NEW_REF(sint, HAL_S64, hal_s64_t, int64_t)
HAL_PIN_NEW_REF(uint, HAL_U64, hal_u64_t, uint64_t)
HAL_PIN_NEW_REF(real, HAL_FLOAT, hal_float_t, real_t)

/* New API port pin (ports have no default). */
int hal_pin_new_port(int comp_id, hal_pin_dir_t dir, hal_port_t ***ref, const char *fmt, ...)
{
    va_list ap;
    int rc;

    va_start(ap, fmt);
    rc = halpr_item_new_ref(1, HAL_PORT, dir, (void **)ref, comp_id, fmt, ap);
    va_end(ap);
    return rc;
}
