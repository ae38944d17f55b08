/* rtapi_bitops.h: atomic bit operations on arrays of unsigned long. */
#ifndef RTAPI_BITOPS_H
#define RTAPI_BITOPS_H

#define RTAPI_BITS_PER_LONG (8 * (int)sizeof(unsigned long))
#define RTAPI_BIT_WORD_(nr, addr) ((addr) + (nr) / RTAPI_BITS_PER_LONG)
#define RTAPI_BIT_MASK_(nr) (1UL << ((nr) % RTAPI_BITS_PER_LONG))

/* Atomically set bit nr. */
static inline void rtapi_set_bit(int nr, volatile unsigned long *addr)
{
    __atomic_fetch_or(RTAPI_BIT_WORD_(nr, addr), RTAPI_BIT_MASK_(nr), __ATOMIC_SEQ_CST);
}

/* Atomically clear bit nr. */
static inline void rtapi_clear_bit(int nr, volatile unsigned long *addr)
{
    __atomic_fetch_and(RTAPI_BIT_WORD_(nr, addr), ~RTAPI_BIT_MASK_(nr), __ATOMIC_SEQ_CST);
}

/* Read bit nr (non-zero when set). */
static inline int rtapi_test_bit(int nr, const volatile unsigned long *addr)
{
    return (__atomic_load_n(RTAPI_BIT_WORD_(nr, addr), __ATOMIC_SEQ_CST)
            & RTAPI_BIT_MASK_(nr)) != 0;
}

/* Atomically set bit nr and return its old value. */
static inline int rtapi_test_and_set_bit(int nr, volatile unsigned long *addr)
{
    return (__atomic_fetch_or(RTAPI_BIT_WORD_(nr, addr), RTAPI_BIT_MASK_(nr),
                              __ATOMIC_SEQ_CST) & RTAPI_BIT_MASK_(nr)) != 0;
}

/* Atomically clear bit nr and return its old value. */
static inline int rtapi_test_and_clear_bit(int nr, volatile unsigned long *addr)
{
    return (__atomic_fetch_and(RTAPI_BIT_WORD_(nr, addr), ~RTAPI_BIT_MASK_(nr),
                               __ATOMIC_SEQ_CST) & RTAPI_BIT_MASK_(nr)) != 0;
}

#define set_bit(nr, addr) rtapi_set_bit(nr, addr)
#define clear_bit(nr, addr) rtapi_clear_bit(nr, addr)
#define test_bit(nr, addr) rtapi_test_bit(nr, addr)
#define test_and_set_bit(nr, addr) rtapi_test_and_set_bit(nr, addr)
#define test_and_clear_bit(nr, addr) rtapi_test_and_clear_bit(nr, addr)
#endif
