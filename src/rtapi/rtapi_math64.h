/* rtapi_math64.h: 64-bit division helpers (plain C division in uspace). */
#ifndef RTAPI_MATH64_H
#define RTAPI_MATH64_H
#include <stdint.h>

/* Unsigned 64/32 division. */
static inline uint64_t rtapi_div_u64(uint64_t dividend, uint32_t divisor)
{
    return dividend / divisor;
}

/* Unsigned 64/32 division that also returns the remainder. */
static inline uint64_t rtapi_div_u64_rem(uint64_t dividend, uint32_t divisor,
                                         uint32_t *remainder)
{
    *remainder = (uint32_t)(dividend % divisor);
    return dividend / divisor;
}

/* Signed 64/32 division. */
static inline int64_t rtapi_div_s64(int64_t dividend, int32_t divisor)
{
    return dividend / divisor;
}

/* Signed 64/32 division that also returns the remainder. */
static inline int64_t rtapi_div_s64_rem(int64_t dividend, int32_t divisor,
                                        int32_t *remainder)
{
    *remainder = (int32_t)(dividend % divisor);
    return dividend / divisor;
}
#endif
