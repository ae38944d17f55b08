/* rtapi_msgqueue.c: lock-free queue for messages printed by SCHED_FIFO tasks; a
   helper thread writes them every 10 ms so realtime tasks never block on I/O. */
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "rtapi.h"
#include "rtapi_internal.h"

#define QUEUE_SLOTS 128
#define SLOT_TEXT 1000
#define WRITER_PERIOD_NS 10000000L

typedef struct {
    unsigned long seq;        /* slot state: == pos free for pos, pos+1 filled */
    int level;
    char text[SLOT_TEXT];
} msg_slot_t;

static msg_slot_t slots[QUEUE_SLOTS];
static unsigned long head, tail;
static unsigned long dropped;
static pthread_once_t init_once = PTHREAD_ONCE_INIT;
static pthread_mutex_t drain_lock = PTHREAD_MUTEX_INITIALIZER;

/* Write every filled slot in order (one consumer at a time). */
void rtapi_msg_flush(void)
{
    unsigned long lost;

    pthread_mutex_lock(&drain_lock);
    for (;;) {
        msg_slot_t *s = &slots[tail % QUEUE_SLOTS];
        if (__atomic_load_n(&s->seq, __ATOMIC_ACQUIRE) != tail + 1)
            break;
        fputs(s->text, s->level == RTAPI_MSG_ALL ? stdout : stderr);
        __atomic_store_n(&s->seq, tail + QUEUE_SLOTS, __ATOMIC_RELEASE);
        tail++;
    }
    lost = __atomic_exchange_n(&dropped, 0, __ATOMIC_ACQ_REL);
    if (lost)
        fprintf(stderr, "rtapi: %lu realtime messages dropped (queue full)\n", lost);
    fflush(stdout);
    fflush(stderr);
    pthread_mutex_unlock(&drain_lock);
}

/* Helper thread: drain the queue every 10 ms. */
static void *writer(void *arg)
{
    struct timespec ts = { 0, WRITER_PERIOD_NS };

    (void)arg;
    for (;;) {
        nanosleep(&ts, NULL);
        rtapi_msg_flush();
    }
    return NULL;
}

/* Mark every slot free and start the writer thread. */
static void queue_init(void)
{
    pthread_t thread;

    for (unsigned long i = 0; i < QUEUE_SLOTS; i++)
        slots[i].seq = i;
    if (pthread_create(&thread, NULL, writer, NULL) == 0)
        pthread_detach(thread);
}

/* Prepare the queue and its writer (call before realtime tasks run). */
void rtapi_msg_queue_start(void)
{
    pthread_once(&init_once, queue_init);
}

/* Queue a formatted message; returns 0, or -1 when not started or full (dropped). */
int rtapi_msg_queue(int level, const char *fmt, va_list ap)
{
    unsigned long pos = __atomic_load_n(&head, __ATOMIC_RELAXED);
    msg_slot_t *s;

    for (;;) {
        long diff;
        s = &slots[pos % QUEUE_SLOTS];
        diff = (long)(__atomic_load_n(&s->seq, __ATOMIC_ACQUIRE) - pos);
        if (diff == 0 && __atomic_compare_exchange_n(&head, &pos, pos + 1, 0,
                                                     __ATOMIC_ACQ_REL, __ATOMIC_RELAXED))
            break;
        if (diff < 0) {
            __atomic_add_fetch(&dropped, 1, __ATOMIC_RELAXED);
            return -1;
        }
        if (diff > 0)
            pos = __atomic_load_n(&head, __ATOMIC_RELAXED);
    }
    s->level = level;
    vsnprintf(s->text, sizeof s->text, fmt, ap);
    __atomic_store_n(&s->seq, pos + 1, __ATOMIC_RELEASE);
    return 0;
}
