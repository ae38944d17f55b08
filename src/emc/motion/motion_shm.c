/* motion_shm.c: command ring, seqlocked status and message queue of the motion segment (lock-free, both sides). */
#include <errno.h>
#include <string.h>
#include "motion_shm.h"

_Static_assert((EMCMOT_RING_CAPACITY & (EMCMOT_RING_CAPACITY - 1)) == 0,
               "ring capacity is a power of two");
_Static_assert((EMCMOT_ERROR_SLOTS & (EMCMOT_ERROR_SLOTS - 1)) == 0,
               "message slots are a power of two");

#define LOAD_ACQ(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)
#define LOAD_RLX(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define STORE_REL(p, v) __atomic_store_n((p), (v), __ATOMIC_RELEASE)

/* Copy at most size-1 bytes of src and terminate. */
static void copy_text(char *dst, size_t size, const char *src)
{
    size_t n = strlen(src);

    if (size == 0)
        return;
    if (n >= size)
        n = size - 1;
    memcpy(dst, src, n);
    dst[n] = '\0';
}

/* Owner: clear the segment, fill the header and publish it with the magic last. */
void emcmot_shm_init(emcmot_shm_t *shm, const char *owner_name, int owner_pid)
{
    emcmot_shm_header_t *h = &shm->header;

    STORE_REL(&h->magic, 0u);
    memset((char *)shm + sizeof h->magic, 0, sizeof *shm - sizeof h->magic);
    h->version = EMCMOT_SHM_VERSION;
    h->size = sizeof(emcmot_shm_t);
    h->command_size = sizeof(emcmot_command_t);
    h->status_size = sizeof(emcmot_status_t);
    h->ring_capacity = EMCMOT_RING_CAPACITY;
    h->error_slots = EMCMOT_ERROR_SLOTS;
    h->error_len = EMCMOT_ERROR_LEN;
    h->owner_pid = owner_pid;
    copy_text(h->owner_name, sizeof h->owner_name, owner_name);
    shm->ring.next_serial = 1;
    for (uint32_t i = 0; i < EMCMOT_ERROR_SLOTS; i++)
        shm->errors.slot[i].seq = i;
    STORE_REL(&h->owner_state, EMCMOT_OWNER_RUNNING);
    STORE_REL(&h->magic, EMCMOT_SHM_MAGIC);
}

/* Owner: tell attached readers the owner is gone. */
void emcmot_shm_retire(emcmot_shm_t *shm)
{
    STORE_REL(&shm->header.owner_state, EMCMOT_OWNER_GONE);
}

/* 0 when the segment matches this build; else -EPROTO and the difference in why. */
int emcmot_shm_check(const emcmot_shm_t *shm, size_t mapped_size, char *why, size_t why_size)
{
    const emcmot_shm_header_t *h = &shm->header;
    const char *what = NULL;

    if (mapped_size < sizeof h->magic || LOAD_ACQ(&h->magic) != EMCMOT_SHM_MAGIC)
        what = "is not initialised (no motion module owns it)";
    else if (h->version != EMCMOT_SHM_VERSION)
        what = "has another interface version";
    else if (h->size != sizeof(emcmot_shm_t) || mapped_size < sizeof(emcmot_shm_t))
        what = "has another size";
    else if (h->command_size != sizeof(emcmot_command_t) ||
             h->status_size != sizeof(emcmot_status_t) ||
             h->ring_capacity != EMCMOT_RING_CAPACITY || h->error_slots != EMCMOT_ERROR_SLOTS ||
             h->error_len != EMCMOT_ERROR_LEN)
        what = "has another command, status or queue layout";
    if (!what)
        return 0;
    if (why && why_size) {
        char text[200];
        copy_text(text, sizeof text, "motion shared memory ");
        strncat(text, what, sizeof text - strlen(text) - 1);
        copy_text(why, why_size, text);
    }
    return -EPROTO;
}

/* Producer: queue a copy of *cmd with the next serial; serial or -EAGAIN. */
long emcmot_ring_push(emcmot_shm_t *shm, emcmot_command_t *cmd)
{
    emcmot_ring_t *r = &shm->ring;
    uint32_t head = LOAD_RLX(&r->head);
    uint32_t tail = LOAD_ACQ(&r->tail);
    uint32_t serial;

    if (head - tail >= EMCMOT_RING_CAPACITY)
        return -EAGAIN;
    serial = r->next_serial;
    r->next_serial = serial + 1 ? serial + 1 : 1;
    cmd->serial = serial;
    r->slot[head & (EMCMOT_RING_CAPACITY - 1)] = *cmd;
    STORE_REL(&r->head, head + 1);
    return (long)serial;
}

/* Consumer: copy the oldest command out (it stays queued); 1, or 0 when empty. */
int emcmot_ring_peek(emcmot_shm_t *shm, emcmot_command_t *out)
{
    emcmot_ring_t *r = &shm->ring;
    uint32_t tail = LOAD_RLX(&r->tail);

    if (LOAD_ACQ(&r->head) == tail)
        return 0;
    *out = r->slot[tail & (EMCMOT_RING_CAPACITY - 1)];
    return 1;
}

/* Consumer: release the oldest slot. */
void emcmot_ring_pop(emcmot_shm_t *shm)
{
    emcmot_ring_t *r = &shm->ring;
    uint32_t tail = LOAD_RLX(&r->tail);

    if (LOAD_ACQ(&r->head) != tail)
        STORE_REL(&r->tail, tail + 1);
}

/* Commands waiting. */
unsigned emcmot_ring_count(const emcmot_shm_t *shm)
{
    return LOAD_ACQ(&shm->ring.head) - LOAD_ACQ(&shm->ring.tail);
}

/* Writer: odd sequence while copying, even when done. */
void emcmot_status_publish(emcmot_shm_t *shm, const emcmot_status_t *status)
{
    emcmot_status_buffer_t *b = &shm->status;
    uint32_t seq = LOAD_RLX(&b->seq);

    STORE_REL(&b->seq, seq + 1);
    __atomic_thread_fence(__ATOMIC_RELEASE);
    memcpy(&b->status, status, sizeof *status);
    STORE_REL(&b->seq, seq + 2);
}

/* Reader: copy until the sequence is even and unchanged around the copy. */
int emcmot_status_read(const emcmot_shm_t *shm, emcmot_status_t *out, int max_tries)
{
    const emcmot_status_buffer_t *b = &shm->status;

    for (int i = 0; i < max_tries; i++) {
        uint32_t before = LOAD_ACQ(&b->seq);
        if (before & 1u)
            continue;
        memcpy(out, &b->status, sizeof *out);
        __atomic_thread_fence(__ATOMIC_ACQUIRE);
        if (LOAD_RLX(&b->seq) == before)
            return 0;
    }
    return -EBUSY;
}

/* Any writer: claim a slot with a compare-and-swap, fill it, hand it to the reader. */
int emcmot_error_push(emcmot_shm_t *shm, int kind, const char *text)
{
    emcmot_error_queue_t *q = &shm->errors;
    uint32_t pos = LOAD_RLX(&q->enqueue_pos);
    emcmot_error_slot_t *slot;

    for (;;) {
        slot = &q->slot[pos & (EMCMOT_ERROR_SLOTS - 1)];
        int32_t diff = (int32_t)(LOAD_ACQ(&slot->seq) - pos);
        if (diff < 0) {
            __atomic_fetch_add(&q->dropped, 1u, __ATOMIC_RELAXED);
            return -ENOSPC;
        }
        if (diff == 0 && __atomic_compare_exchange_n(&q->enqueue_pos, &pos, pos + 1, 0,
                                                     __ATOMIC_RELAXED, __ATOMIC_RELAXED))
            break;
        if (diff > 0)
            pos = LOAD_RLX(&q->enqueue_pos);
    }
    slot->kind = kind;
    copy_text(slot->text, sizeof slot->text, text ? text : "");
    STORE_REL(&slot->seq, pos + 1);
    return 0;
}

/* Reader: take the oldest filled slot; 1, or 0 when none is ready. */
int emcmot_error_pop(emcmot_shm_t *shm, int *kind, char *buf, size_t size)
{
    emcmot_error_queue_t *q = &shm->errors;
    uint32_t pos = LOAD_RLX(&q->dequeue_pos);
    emcmot_error_slot_t *slot = &q->slot[pos & (EMCMOT_ERROR_SLOTS - 1)];

    if (LOAD_ACQ(&slot->seq) != pos + 1)
        return 0;
    if (kind)
        *kind = slot->kind;
    copy_text(buf, size, slot->text);
    STORE_REL(&slot->seq, pos + EMCMOT_ERROR_SLOTS);
    STORE_REL(&q->dequeue_pos, pos + 1);
    return 1;
}

/* Result of serial in an echo; 1 handled, 0 not yet, -ENODATA result no longer kept. */
int emcmot_echo_lookup(const emcmot_echo_t *echo, uint32_t serial, int *result,
                       char *reason, size_t reason_size)
{
    uint32_t oldest = 0;

    if (echo->handled == 0 || (int32_t)(echo->serial - serial) < 0)
        return 0;
    if (reason && reason_size)
        reason[0] = '\0';
    for (int i = 0; i < EMCMOT_REJECT_HISTORY; i++) {
        const emcmot_reject_t *r = &echo->reject[i];
        if (r->serial == 0)
            continue;
        if (r->serial == serial) {
            *result = r->result;
            if (reason)
                copy_text(reason, reason_size, r->reason);
            return 1;
        }
        if (oldest == 0 || (int32_t)(r->serial - oldest) < 0)
            oldest = r->serial;
    }
    if (echo->rejected > EMCMOT_REJECT_HISTORY && (int32_t)(serial - oldest) < 0)
        return -ENODATA;
    *result = EMCMOT_COMMAND_OK;
    return 1;
}
