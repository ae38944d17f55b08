/* hal_stream.c: streams (spec/hal.md §9): lock-free SPSC record FIFO in its own shm segment per key. */
#include "hal_internal.h"
#include <ctype.h>
#include <time.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#define HAL_STREAM_MAGIC 0x4f455354

/* The shared segment: header then depth slots of (num_pins + 1) values (last = sample no). */
struct hal_stream_shm {
    unsigned magic;
    volatile unsigned in;            /* next slot to write */
    volatile unsigned out;           /* next slot to read */
    unsigned this_sample;            /* sample number of the last write (records are numbered from 1) */
    int depth;                       /* slots; holds depth-1 records */
    int num_pins;
    volatile int num_overruns;
    volatile int num_underruns;
    hal_type_t type[HAL_STREAM_MAX_PINS];
    union hal_stream_data data[];
};

/* Parse a type string (f/r b s u l k, any case) into types; count or <0. */
static int hal_stream_parse(const char *cfg, hal_type_t *types)
{
    static const char letters[] = "frbsulk";
    static const hal_type_t map[] = {HAL_FLOAT, HAL_FLOAT, HAL_BIT, HAL_S32, HAL_U32, HAL_S64, HAL_U64};
    int n = 0;

    for (; cfg && *cfg; cfg++) {
        const char *p = strchr(letters, tolower((unsigned char)*cfg));
        if (!p || !*cfg) {
            HAL_ERR("stream: invalid type character '%c'\n", *cfg);
            return -EINVAL;
        }
        if (n == HAL_STREAM_MAX_PINS) {
            HAL_ERR("stream: more than %d fields\n", HAL_STREAM_MAX_PINS);
            return -EINVAL;
        }
        types[n++] = map[p - letters];
    }
    if (n == 0) {
        HAL_ERR("stream: empty type string\n");
        return -EINVAL;
    }
    return n;
}

/* Bytes of a segment for depth slots of n fields. */
static size_t hal_stream_bytes(int depth, int n)
{
    return sizeof(struct hal_stream_shm) + (size_t)depth * (n + 1) * sizeof(union hal_stream_data);
}

/* Get (creating exclusively) the segment id, removing a stale unattached one. */
static int hal_stream_get_new(int key, size_t size)
{
    struct shmid_ds ds;
    int id = shmget(key, size, IPC_CREAT | IPC_EXCL | 0600);

    if (id < 0 && errno == EEXIST) {
        id = shmget(key, 0, 0600);
        if (id >= 0 && shmctl(id, IPC_STAT, &ds) == 0 && ds.shm_nattch == 0) {
            shmctl(id, IPC_RMID, NULL);
            id = shmget(key, size, IPC_CREAT | IPC_EXCL | 0600);
        } else {
            errno = EEXIST;
            id = -1;
        }
    }
    return id;
}

/* Create a stream segment for `key` holding depth-1 records of typestring fields. */
int hal_stream_create(hal_stream_t *stream, int comp_id, int key, int depth, const char *typestring)
{
    hal_type_t types[HAL_STREAM_MAX_PINS];
    int n = hal_stream_parse(typestring, types);
    int id;
    void *p;

    if (n < 0)
        return n;
    if (depth < 2) {
        HAL_ERR("stream: depth %d must be at least 2\n", depth);
        return -EINVAL;
    }
    if (rtapi_instance() < 0)
        return -EINVAL;
    id = hal_stream_get_new(rtapi_instance_key(key), hal_stream_bytes(depth, n));
    if (id < 0) {
        HAL_ERR("stream: could not create shared memory for key 0x%x: %s\n", key, strerror(errno));
        return errno == EEXIST ? -EEXIST : -ENOMEM;
    }
    p = shmat(id, NULL, 0);
    if (p == (void *)-1) {
        shmctl(id, IPC_RMID, NULL);
        return -ENOMEM;
    }
    stream->comp_id = comp_id;
    stream->shmem_id = id;
    stream->fifo = p;
    stream->fifo->depth = depth;
    stream->fifo->num_pins = n;
    memcpy(stream->fifo->type, types, sizeof(types));
    __atomic_store_n(&stream->fifo->magic, HAL_STREAM_MAGIC, __ATOMIC_RELEASE);
    return 0;
}

/* Detach and remove the segment (it vanishes when the last user detaches). */
void hal_stream_destroy(hal_stream_t *stream)
{
    int id = stream->shmem_id;
    hal_stream_detach(stream);
    shmctl(id, IPC_RMID, NULL);
}

/* Check an attached segment against an optional type string. */
static int hal_stream_check(struct hal_stream_shm *f, const char *typestring)
{
    hal_type_t types[HAL_STREAM_MAX_PINS];
    int n;

    if (f->magic != HAL_STREAM_MAGIC) {
        HAL_ERR("stream: shared memory has the wrong magic number\n");
        return -EINVAL;
    }
    if (!typestring || !*typestring)
        return 0;
    n = hal_stream_parse(typestring, types);
    if (n < 0)
        return n;
    if (n != f->num_pins || memcmp(types, f->type, n * sizeof(hal_type_t)) != 0) {
        HAL_ERR("stream: type string '%s' does not match the stream\n", typestring);
        return -EINVAL;
    }
    return 0;
}

/* Attach to an existing stream of `key`; a missing stream is -ENOENT without a message
   (callers such as halsampler report it in their own words). */
int hal_stream_attach(hal_stream_t *stream, int comp_id, int key, const char *typestring)
{
    int id;
    void *p;
    int rc;

    if (rtapi_instance() < 0)
        return -EINVAL;
    id = shmget(rtapi_instance_key(key), 0, 0600);
    if (id < 0)
        return -ENOENT;
    p = shmat(id, NULL, 0);
    if (p == (void *)-1)
        return -ENOMEM;
    rc = hal_stream_check(p, typestring);
    if (rc < 0) {
        shmdt(p);
        return rc;
    }
    stream->comp_id = comp_id;
    stream->shmem_id = id;
    stream->fifo = p;
    return 0;
}

/* Unmap the stream. */
int hal_stream_detach(hal_stream_t *stream)
{
    if (stream->fifo)
        shmdt((void *)stream->fifo);
    stream->fifo = NULL;
    stream->shmem_id = -1;
    return 0;
}

/* Fields per record. */
int hal_stream_element_count(hal_stream_t *stream)
{
    return stream->fifo->num_pins;
}

/* Type of field idx (HAL_TYPE_UNINITIALIZED when out of range). */
hal_type_t hal_stream_element_type(hal_stream_t *stream, int idx)
{
    if (idx < 0 || idx >= stream->fifo->num_pins)
        return HAL_TYPE_UNINITIALIZED;
    return stream->fifo->type[idx];
}

/* Records currently queued. */
int hal_stream_depth(hal_stream_t *stream)
{
    struct hal_stream_shm *f = stream->fifo;
    unsigned in = __atomic_load_n(&f->in, __ATOMIC_ACQUIRE);
    unsigned out = __atomic_load_n(&f->out, __ATOMIC_ACQUIRE);
    return (int)((in + f->depth - out) % f->depth);
}

/* The depth the stream was created with (it holds one record less). */
int hal_stream_maxdepth(hal_stream_t *stream)
{
    return stream->fifo->depth;
}

/* Reads attempted on an empty stream. */
int hal_stream_num_underruns(hal_stream_t *stream) { return stream->fifo->num_underruns; }
/* Writes attempted on a full stream. */
int hal_stream_num_overruns(hal_stream_t *stream) { return stream->fifo->num_overruns; }

/* Non-zero when a record can be read. */
bool hal_stream_readable(hal_stream_t *stream)
{
    return hal_stream_depth(stream) > 0;
}

/* Non-zero when a record can be written. */
bool hal_stream_writable(hal_stream_t *stream)
{
    return hal_stream_depth(stream) < stream->fifo->depth - 1;
}

/* Read one record and its sample number; -EAGAIN (underrun counted) when empty. */
int hal_stream_read(hal_stream_t *stream, union hal_stream_data *buf, unsigned *sampleno)
{
    struct hal_stream_shm *f = stream->fifo;
    union hal_stream_data *slot;
    unsigned out;

    if (!hal_stream_readable(stream)) {
        f->num_underruns++;
        return -EAGAIN;
    }
    out = f->out;
    slot = &f->data[(size_t)out * (f->num_pins + 1)];
    memcpy(buf, slot, f->num_pins * sizeof(*buf));
    if (sampleno)
        *sampleno = slot[f->num_pins].u;
    __atomic_store_n(&f->out, (out + 1) % f->depth, __ATOMIC_RELEASE);
    return 0;
}

/* Write one record; -ENOSPC (overrun counted, sample number kept) when full. */
int hal_stream_write(hal_stream_t *stream, union hal_stream_data *buf)
{
    struct hal_stream_shm *f = stream->fifo;
    union hal_stream_data *slot;
    unsigned in;

    if (!hal_stream_writable(stream)) {
        f->num_overruns++;
        return -ENOSPC;
    }
    in = f->in;
    slot = &f->data[(size_t)in * (f->num_pins + 1)];
    memcpy(slot, buf, f->num_pins * sizeof(*buf));
    slot[f->num_pins].u = ++f->this_sample;
    __atomic_store_n(&f->in, (in + 1) % f->depth, __ATOMIC_RELEASE);
    return 0;
}

/* Poll every 10 ms until test(stream) or *stop. */
static void hal_stream_wait(hal_stream_t *stream, sig_atomic_t *stop, bool (*test)(hal_stream_t *))
{
    struct timespec ts = {0, 10000000};
    while (!(stop && *stop) && !test(stream))
        nanosleep(&ts, NULL);
}

/* Wait until a record can be written (or *stop). */
void hal_stream_wait_writable(hal_stream_t *stream, sig_atomic_t *stop)
{
    hal_stream_wait(stream, stop, hal_stream_writable);
}

/* Wait until a record can be read (or *stop). */
void hal_stream_wait_readable(hal_stream_t *stream, sig_atomic_t *stop)
{
    hal_stream_wait(stream, stop, hal_stream_readable);
}
