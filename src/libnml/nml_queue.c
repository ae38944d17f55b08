/* nml_queue.c: queued buffers: a ring of records, oldest first; a full queue refuses the write. */
#include <errno.h>
#include <string.h>

#include "nml_shm.h"

/* Ring bytes a message of size bytes takes, header included. */
static uint32_t record_bytes(uint32_t size)
{
    return (uint32_t)((sizeof(nml_record_t) + size + NML_ALIGN - 1) & ~(NML_ALIGN - 1));
}

/* Offset where a record of need bytes goes, or -1 when it does not fit now. Sets *wrap
 * when it goes to offset 0 and the rest of the ring up to the end is skipped. */
static int64_t queue_place(const nml_shm_t *shm, uint32_t need, int *wrap)
{
    *wrap = 0;
    if (shm->count == 0)
        return need <= shm->data_size ? 0 : -1;
    if (shm->tail == shm->head)
        return -1; /* exactly full */
    if (shm->tail > shm->head) {
        if (need <= shm->data_size - shm->tail)
            return shm->tail;
        if (need <= shm->head) {
            *wrap = 1;
            return 0;
        }
        return -1;
    }
    return need <= shm->head - shm->tail ? (int64_t)shm->tail : -1;
}

/* Move head past the end of the ring (a gap too small for a record, or a wrap marker) to the
 * start, where the oldest record then is.  A head left at the end looked to queue_place like free
 * room up to the end while the ring was full: a second writer process overwrote unread records. */
static void queue_normalize_head(nml_shm_t *shm)
{
    if (shm->count == 0 || shm->head > shm->data_size)
        return;
    if (shm->data_size - shm->head < sizeof(nml_record_t) ||
        ((nml_record_t *)(shm->data + shm->head))->size == NML_RECORD_WRAP)
        shm->head = 0;
}

/* Append a message; -EAGAIN when it does not fit now (nothing changes then). */
int nml_queue_write(struct nml_channel *ch, const void *msg, uint32_t size, int32_t *serial)
{
    nml_shm_t *shm = ch->shm;
    uint32_t need = record_bytes(size);
    nml_record_t *rec;
    uint64_t count;
    int64_t at;
    int wrap;

    if (need > shm->data_size)
        return -EMSGSIZE;
    nml_lock(shm);
    if (shm->count == 0)
        shm->head = shm->tail = 0;
    queue_normalize_head(shm);
    at = queue_place(shm, need, &wrap);
    if (at < 0) {
        nml_unlock(shm);
        return -EAGAIN;
    }
    if (wrap && shm->data_size - shm->tail >= sizeof(nml_record_t))
        ((nml_record_t *)(shm->data + shm->tail))->size = NML_RECORD_WRAP;
    count = __atomic_load_n(&shm->write_count, __ATOMIC_RELAXED) + 1;
    rec = (nml_record_t *)(shm->data + at);
    rec->size = size;
    rec->reserved = 0;
    rec->write_count = count;
    memcpy(rec + 1, msg, size);
    if (shm->flags & NML_FLAG_SERIAL)
        ((nml_msg_hdr_t *)(rec + 1))->serial_number = nml_serial_of(count);
    shm->tail = (uint32_t)at + need;
    if (shm->tail == shm->data_size)
        shm->tail = 0;
    shm->count++;
    __atomic_store_n(&shm->write_count, count, __ATOMIC_RELEASE);
    nml_notify(shm);
    nml_unlock(shm);
    if (serial)
        *serial = nml_serial_of(count);
    return 0;
}

/* The record at head (following a wrap), or NULL when the ring is inconsistent. */
static nml_record_t *queue_head(nml_shm_t *shm)
{
    nml_record_t *rec;

    if (shm->head > shm->data_size)
        return NULL;
    if (shm->data_size - shm->head < sizeof(nml_record_t))
        shm->head = 0;
    rec = (nml_record_t *)(shm->data + shm->head);
    if (rec->size == NML_RECORD_WRAP) {
        shm->head = 0;
        rec = (nml_record_t *)shm->data;
    }
    if (rec->size < sizeof(nml_msg_hdr_t) || record_bytes(rec->size) > shm->data_size - shm->head)
        return NULL;
    return rec;
}

/* Drop every record of a ring found inconsistent; -EIO. */
static int queue_reset(nml_shm_t *shm)
{
    shm->head = shm->tail = shm->count = 0;
    nml_notify(shm);
    return -EIO;
}

/* Copy the oldest message; remove it when `remove`. Bytes, 0 when empty, or -errno. */
int nml_queue_read(struct nml_channel *ch, void *buf, size_t cap, int remove)
{
    nml_shm_t *shm = ch->shm;
    nml_record_t *rec;
    int size;

    nml_lock(shm);
    if (shm->count == 0) {
        nml_unlock(shm);
        return 0;
    }
    rec = queue_head(shm);
    if (!rec) {
        size = queue_reset(shm);
        nml_unlock(shm);
        return size;
    }
    if (rec->size > cap) {
        nml_unlock(shm);
        return -EMSGSIZE;
    }
    memcpy(buf, rec + 1, rec->size);
    size = (int)rec->size;
    ch->last_read_count = rec->write_count;
    if (remove) {
        shm->head += record_bytes(rec->size);
        if (--shm->count == 0)
            shm->head = shm->tail = 0;
        queue_normalize_head(shm);
        nml_notify(shm);
    }
    nml_unlock(shm);
    return size;
}
