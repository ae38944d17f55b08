/* hal_port.c: port byte FIFOs (spec/hal.md §9): one writer, one reader, N-byte ring holds N-1. */
#include "hal_internal.h"
#include <time.h>

#define HAL_PORT_MAX_SIZE 65536

/* A port ring in HAL memory; the handle is its offset. */
typedef struct {
    volatile unsigned read;     /* next byte to read */
    volatile unsigned write;    /* next byte to write */
    unsigned size;              /* ring bytes */
    char buff[];
} hal_port_shm_t;

/* The ring behind a port (its handle), or NULL for a NULL port, handle 0 or no HAL. */
static hal_port_shm_t *hal_port_ring(const hal_port_t *port)
{
    if (!port || !*port || !hal_data)
        return NULL;
    return (hal_port_shm_t *)(hal_shmem_base + *port);
}

/* Allocate a port ring of `size` bytes in HAL memory; *port gets its handle. */
int hal_port_alloc(unsigned size, hal_port_t *port)
{
    hal_port_shm_t *ring;

    if (!hal_data) {
        HAL_ERR("port_alloc called before init\n");
        return -EINVAL;
    }
    if (size < 1 || size > HAL_PORT_MAX_SIZE) {
        HAL_ERR("port size %u is not between 1 and %d\n", size, HAL_PORT_MAX_SIZE);
        return -EINVAL;
    }
    ring = hal_malloc(sizeof(hal_port_shm_t) + size);
    if (!ring)
        return -ENOMEM;
    ring->size = size;
    *port = SHMOFF(ring);
    return 0;
}

/* Bytes ready to read. */
unsigned hal_port_readable(const hal_port_t *port)
{
    hal_port_shm_t *r = hal_port_ring(port);
    unsigned rd, wr;

    if (!r)
        return 0;
    rd = __atomic_load_n(&r->read, __ATOMIC_ACQUIRE);
    wr = __atomic_load_n(&r->write, __ATOMIC_ACQUIRE);
    return (wr + r->size - rd) % r->size;
}

/* Bytes that can be written. */
unsigned hal_port_writable(const hal_port_t *port)
{
    hal_port_shm_t *r = hal_port_ring(port);
    return r ? r->size - 1 - hal_port_readable(port) : 0;
}

/* Ring size in bytes; reports (and returns 0 for) an unallocated port. */
unsigned hal_port_buffer_size(const hal_port_t *port)
{
    hal_port_shm_t *r = hal_port_ring(port);
    if (!r) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hal_port_buffer_size: invalid port 0x%x\n", port ? (unsigned)*port : 0u);
        return 0;
    }
    return r->size;
}

/* Copy count bytes starting at ring offset `from` into dest (with wrap). */
static void hal_port_copy_out(hal_port_shm_t *r, unsigned from, char *dest, unsigned count)
{
    unsigned first = r->size - from < count ? r->size - from : count;
    memcpy(dest, r->buff + from, first);
    memcpy(dest + first, r->buff, count - first);
}

/* Copy count bytes all-or-nothing without consuming them. */
bool hal_port_peek(const hal_port_t *port, char *dest, unsigned count)
{
    hal_port_shm_t *r = hal_port_ring(port);

    if (!r || count > hal_port_readable(port))
        return false;
    hal_port_copy_out(r, __atomic_load_n(&r->read, __ATOMIC_ACQUIRE), dest, count);
    return true;
}

/* Consume count bytes previously peeked (all-or-nothing). */
bool hal_port_peek_commit(const hal_port_t *port, unsigned count)
{
    hal_port_shm_t *r = hal_port_ring(port);

    if (!r || count > hal_port_readable(port))
        return false;
    __atomic_store_n(&r->read, (r->read + count) % r->size, __ATOMIC_RELEASE);
    return true;
}

/* Read count bytes all-or-nothing. */
bool hal_port_read(const hal_port_t *port, char *dest, unsigned count)
{
    return hal_port_peek(port, dest, count) && hal_port_peek_commit(port, count);
}

/* Write count bytes all-or-nothing. */
bool hal_port_write(const hal_port_t *port, const char *src, unsigned count)
{
    hal_port_shm_t *r = hal_port_ring(port);
    unsigned wr, first;

    if (!r || count > hal_port_writable(port))
        return false;
    wr = r->write;
    first = r->size - wr < count ? r->size - wr : count;
    memcpy(r->buff + wr, src, first);
    memcpy(r->buff, src + first, count - first);
    __atomic_store_n(&r->write, (wr + count) % r->size, __ATOMIC_RELEASE);
    return true;
}

/* Drop everything queued (reader side). */
void hal_port_clear(const hal_port_t *port)
{
    hal_port_shm_t *r = hal_port_ring(port);
    if (r)
        __atomic_store_n(&r->read, __atomic_load_n(&r->write, __ATOMIC_ACQUIRE), __ATOMIC_RELEASE);
}

/* Poll every 10 ms until test(**port) >= count or *stop is set. */
static void hal_port_wait(hal_port_t **port, unsigned count, sig_atomic_t *stop,
                          unsigned (*test)(const hal_port_t *))
{
    struct timespec ts = {0, 10000000};
    while (!(stop && *stop) && test(*port) < count)
        nanosleep(&ts, NULL);
}

/* Wait until count bytes are readable. */
void hal_port_wait_readable(hal_port_t **port, unsigned count, sig_atomic_t *stop)
{
    hal_port_wait(port, count, stop, hal_port_readable);
}

/* Wait until count bytes are writable. */
void hal_port_wait_writable(hal_port_t **port, unsigned count, sig_atomic_t *stop)
{
    hal_port_wait(port, count, stop, hal_port_writable);
}
