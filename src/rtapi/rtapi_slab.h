/* rtapi_slab.h: kernel-style allocation names mapped to the malloc family. */
#ifndef RTAPI_SLAB_H
#define RTAPI_SLAB_H
#include <stdlib.h>
#include <string.h>

#define RTAPI_GFP_KERNEL 0
#define RTAPI_GFP_ATOMIC 0
#define RTAPI_GFP_USER 0

/* Allocate size bytes (flags ignored in uspace). */
static inline void *rtapi_kmalloc(size_t size, int flags)
{
    (void)flags;
    return malloc(size);
}

/* Allocate size zeroed bytes. */
static inline void *rtapi_kzalloc(size_t size, int flags)
{
    (void)flags;
    return calloc(1, size);
}

/* Resize an allocation. */
static inline void *rtapi_krealloc(void *ptr, size_t size, int flags)
{
    (void)flags;
    return realloc(ptr, size);
}

/* Free an allocation. */
static inline void rtapi_kfree(void *ptr)
{
    free(ptr);
}
#endif
