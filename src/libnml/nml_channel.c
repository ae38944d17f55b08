/* nml_channel.c: opening a buffer as a process of a .nml file; access checks and the public read/write/wait calls. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include <time.h>

#include "nml_shm.h"

/* True when host names this machine: localhost, a 127.x.y.z or ::1 address, or our own
   host name. A REMOTE line for this machine reaches the same shared memory as LOCAL
   (LinuxCNC would go through linuxcncsvr's TCP port; OpenEMC serves nothing there). */
static int host_is_this_machine(const char *host)
{
    char self[256];

    if (!strcasecmp(host, "localhost") || !strncasecmp(host, "localhost.", 10) ||
        !strncmp(host, "127.", 4) || !strcmp(host, "::1"))
        return 1;
    if (gethostname(self, sizeof self) == 0) {
        self[sizeof self - 1] = 0;
        if (!strcasecmp(host, self))
            return 1;
    }
    return 0;
}

/* Find the B and P lines of a buffer and process; 0 or -EINVAL with err set. */
static int find_lines(const nml_config_t *cfg, const char *buffer, const char *process,
                      struct nml_channel *ch, char *err, size_t errlen)
{
    const nml_buffer_cfg_t *b = nml_config_buffer(cfg, buffer);
    const nml_process_cfg_t *p;

    if (!b) {
        snprintf(err, errlen, "%s: no buffer '%s' (no B line)", cfg->path, buffer);
        return -EINVAL;
    }
    p = nml_config_process(cfg, process, buffer);
    if (!p) {
        snprintf(err, errlen, "%s: process '%s' has no P line for buffer '%s'", cfg->path,
                 process, buffer);
        return -EINVAL;
    }
    if (p->remote && !host_is_this_machine(p->host)) {
        snprintf(err, errlen, "%s:%d: process '%s' reaches buffer '%s' REMOTE on host '%s'; "
                 "OpenEMC serves NML buffers on this machine only", cfg->path, p->line,
                 process, buffer, p->host);
        return -EINVAL;
    }
    ch->buffer = *b;
    ch->process = *p;
    return 0;
}

/* Open with a parsed file. */
nml_channel_t *nml_open_config(const nml_config_t *cfg, const char *buffer, const char *process,
                               char *err, size_t errlen)
{
    struct nml_channel *ch = calloc(1, sizeof *ch);
    int rc;

    if (!ch) {
        snprintf(err, errlen, "%s: out of memory", buffer);
        errno = ENOMEM;
        return NULL;
    }
    rc = find_lines(cfg, buffer, process, ch, err, errlen);
    if (rc == 0)
        rc = nml_segment_open(ch, err, errlen);
    if (rc < 0) {
        free(ch);
        errno = -rc;
        return NULL;
    }
    return ch;
}

/* Open by file name. */
nml_channel_t *nml_open(const char *path, const char *buffer, const char *process, char *err,
                        size_t errlen)
{
    nml_config_t *cfg = nml_config_load(path, err, errlen);
    nml_channel_t *ch;
    int saved;

    if (!cfg) {
        errno = EINVAL;
        return NULL;
    }
    ch = nml_open_config(cfg, buffer, process, err, errlen);
    saved = errno;
    nml_config_free(cfg);
    errno = saved;
    return ch;
}

/* Close a channel. */
void nml_close(nml_channel_t *ch)
{
    if (!ch)
        return;
    nml_segment_close(ch);
    free(ch);
}

/* Shared checks of read and write: access and liveness. */
static int usable(const nml_channel_t *ch, unsigned need)
{
    if (!(ch->process.access & need))
        return -EACCES;
    if (!__atomic_load_n(&ch->shm->alive, __ATOMIC_ACQUIRE))
        return -ESHUTDOWN;
    return 0;
}

/* Write a message. */
int nml_write(nml_channel_t *ch, const void *msg, int32_t *serial)
{
    nml_msg_hdr_t head;
    int rc = usable(ch, NML_ACCESS_W);

    if (rc < 0)
        return rc;
    memcpy(&head, msg, sizeof head);
    if (head.size < sizeof head)
        return -EINVAL;
    if (ch->shm->flags & NML_FLAG_QUEUE)
        return nml_queue_write(ch, msg, head.size, serial);
    return nml_latest_write(ch, msg, head.size, serial);
}

/* Read (consume / mark) a message. */
int nml_read(nml_channel_t *ch, void *buf, size_t cap)
{
    int rc = usable(ch, NML_ACCESS_R);

    if (rc < 0)
        return rc;
    if (ch->shm->flags & NML_FLAG_QUEUE)
        return nml_queue_read(ch, buf, cap, 1);
    return nml_latest_read(ch, buf, cap, 1);
}

/* Peek at a message. */
int nml_peek(nml_channel_t *ch, void *buf, size_t cap)
{
    int rc = usable(ch, NML_ACCESS_R);

    if (rc < 0)
        return rc;
    if (ch->shm->flags & NML_FLAG_QUEUE)
        return nml_queue_read(ch, buf, cap, 0);
    return nml_latest_read(ch, buf, cap, 0);
}

/* Change counter. */
uint32_t nml_change_count(const nml_channel_t *ch)
{
    return __atomic_load_n(&ch->shm->change, __ATOMIC_ACQUIRE);
}

/* Monotonic nanoseconds. */
static int64_t mono_ns(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Sleep until the change counter moves away from seen (futex wakes may be spurious). */
int nml_wait_change(nml_channel_t *ch, uint32_t seen, int64_t timeout_ns)
{
    int64_t deadline = timeout_ns >= 0 ? mono_ns() + timeout_ns : 0;
    int64_t left = timeout_ns;
    int rc;

    for (;;) {
        if (!__atomic_load_n(&ch->shm->alive, __ATOMIC_ACQUIRE))
            return -ESHUTDOWN;
        if (nml_change_count(ch) != seen)
            return 0;
        if (timeout_ns >= 0) {
            left = deadline - mono_ns();
            if (left <= 0)
                return -ETIMEDOUT;
        }
        rc = nml_futex_wait(ch->shm, seen, left);
        if (rc == -EINTR)
            return rc;
    }
}

/* Messages queued. */
int nml_queue_count(const nml_channel_t *ch)
{
    if (!(ch->shm->flags & NML_FLAG_QUEUE))
        return 0;
    return (int)__atomic_load_n(&ch->shm->count, __ATOMIC_ACQUIRE);
}

/* Writes so far. */
uint64_t nml_write_count(const nml_channel_t *ch)
{
    return __atomic_load_n(&ch->shm->write_count, __ATOMIC_ACQUIRE);
}

/* Write count of the message last copied by this channel. */
uint64_t nml_last_read_count(const nml_channel_t *ch)
{
    return ch->last_read_count;
}

/* Liveness. */
int nml_alive(const nml_channel_t *ch)
{
    return (int)__atomic_load_n(&ch->shm->alive, __ATOMIC_ACQUIRE);
}

/* B line of the channel. */
const nml_buffer_cfg_t *nml_channel_buffer(const nml_channel_t *ch)
{
    return &ch->buffer;
}

/* P line of the channel. */
const nml_process_cfg_t *nml_channel_process(const nml_channel_t *ch)
{
    return &ch->process;
}

/* Largest message the buffer takes. */
size_t nml_max_message(const nml_channel_t *ch)
{
    if (ch->shm->flags & NML_FLAG_QUEUE)
        return ch->shm->data_size - sizeof(nml_record_t);
    return ch->shm->data_size;
}
