/* hal_param_typed.c: the typed param constructors and setters. */
#include "hal_internal.h"
#include <stdarg.h>

/* Classic constructors (caller supplies storage) and printf-style variants. */
#define HAL_PARAM_NEW(T, TYPE, CT)                                                 \
    int hal_param_##T##_new(const char *name, hal_param_dir_t dir, CT *data_addr,  \
                            int comp_id)                                           \
    {                                                                              \
        return hal_param_new(name, TYPE, dir, (void *)data_addr, comp_id);         \
    }                                                                              \
    int hal_param_##T##_newf(hal_param_dir_t dir, CT *data_addr, int comp_id,      \
                             const char *fmt, ...)                                 \
    {                                                                              \
        va_list ap;                                                                \
        int rc;                                                                    \
        va_start(ap, fmt);                                                         \
        rc = halpr_item_new_va(0, TYPE, dir, (void *)data_addr, comp_id, fmt, ap); \
        va_end(ap);                                                                \
        return rc;                                                                 \
    }

HAL_PARAM_NEW(bit, HAL_BIT, hal_bit_t)
HAL_PARAM_NEW(float, HAL_FLOAT, hal_float_t)
HAL_PARAM_NEW(u32, HAL_U32, hal_u32_t)
HAL_PARAM_NEW(s32, HAL_S32, hal_s32_t)
HAL_PARAM_NEW(u64, HAL_U64, hal_u64_t)
HAL_PARAM_NEW(s64, HAL_S64, hal_s64_t)

/* New API constructors: HAL allocates the cell, start value dflt. */
#define HAL_PARAM_NEW_REF(T, TYPE, CT, DT)                                     \
    int hal_param_new_##T(int comp_id, hal_param_dir_t dir, CT **ref, DT dflt, \
                          const char *fmt, ...)                                \
    {                                                                          \
        va_list ap;                                                            \
        int rc;                                                                \
        va_start(ap, fmt);                                                     \
        rc = halpr_item_new_ref(0, TYPE, dir, (void **)ref, comp_id, fmt, ap); \
        va_end(ap);                                                            \
        if (rc == 0)                                                           \
            **ref = dflt;                                                      \
        return rc;                                                             \
    }

HAL_PARAM_NEW_REF(bool, HAL_BIT, hal_bit_t, bool)
HAL_PARAM_NEW_REF(si32, HAL_S32, hal_s32_t, int32_t)
HAL_PARAM_NEW_REF(ui32, HAL_U32, hal_u32_t, uint32_t)
HAL_PARAM_NEW_REF(sint, HAL_S64, hal_s64_t, int64_t)
HAL_PARAM_NEW_REF(uint, HAL_U64, hal_u64_t, uint64_t)
HAL_PARAM_NEW_REF(real, HAL_FLOAT, hal_float_t, real_t)

/* Typed setters by name. */
int hal_param_bit_set(const char *name, int value)
{
    hal_bit_t v = value != 0;
    return hal_param_set(name, HAL_BIT, (void *)&v);
}

/* Set a float param by name. */
int hal_param_float_set(const char *name, double value)
{
    hal_float_t v = value;
    return hal_param_set(name, HAL_FLOAT, (void *)&v);
}

/* Set a u32 param by name. */
int hal_param_u32_set(const char *name, unsigned long value)
{
    hal_u32_t v = value;
    return hal_param_set(name, HAL_U32, (void *)&v);
}

/* Set a s32 param by name. */
int hal_param_s32_set(const char *name, signed long value)
{
    hal_s32_t v = value;
    return hal_param_set(name, HAL_S32, (void *)&v);
}

/* Set a u64 param by name. */
int hal_param_u64_set(const char *name, uint64_t value)
{
    hal_u64_t v = value;
    return hal_param_set(name, HAL_U64, (void *)&v);
}

/* Set a s64 param by name. */
int hal_param_s64_set(const char *name, int64_t value)
{
    hal_s64_t v = value;
    return hal_param_set(name, HAL_S64, (void *)&v);
}
