/* nml.h: libnml, CMS shared-memory buffers configured by LinuxCNC .nml files (queues, snapshots, serials). */
#ifndef NML_H
#define NML_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Every message starts with this header (C++: struct NMLmsg in nml_base.hh). */
typedef struct nml_msg_hdr {
    int32_t type;          /* NMLTYPE, e.g. EMC_TASK_SET_MODE_TYPE */
    uint32_t size;         /* bytes of the whole message, this header included */
    int32_t serial_number; /* stamped from the buffer's write counter when it has `serial` */
    uint32_t reserved;     /* 0 */
} nml_msg_hdr_t;

/* ------------------------------------------------------------------ configuration */

#define NML_NAME_MAX 48
#define NML_HOST_MAX 64

/* B-line options that change behaviour (others, e.g. TCP=5005 or xdr, are accepted and ignored). */
enum nml_buffer_flag {
    NML_FLAG_QUEUE = 1,         /* several messages, oldest read first, writer told when full */
    NML_FLAG_CONFIRM_WRITE = 2, /* latest-value buffer: a write is refused until the last one was read */
    NML_FLAG_SERIAL = 4,        /* stamp serial_number from the buffer's write counter */
};

/* P-line access. */
enum nml_access {
    NML_ACCESS_R = 1,
    NML_ACCESS_W = 2,
    NML_ACCESS_RW = 3,
};

/* One B line: B name type host size neut rpc# buffer# max_procs key [options]. */
typedef struct nml_buffer_cfg {
    char name[NML_NAME_MAX];
    char host[NML_HOST_MAX];
    uint32_t size;      /* data bytes: the largest message (latest-value) or the queue capacity */
    int neutral;
    int buffer_number;
    int max_procs;
    int key;            /* key as written; nml_buffer_key() gives this instance's key */
    unsigned flags;     /* NML_FLAG_* */
    int line;           /* line of the B line in the file */
} nml_buffer_cfg_t;

/* One P line: P name buffer LOCAL|REMOTE host R|W|RW server timeout master c_num. */
typedef struct nml_process_cfg {
    char name[NML_NAME_MAX];
    char buffer[NML_NAME_MAX]; /* "default" = every buffer without a line of its own */
    char host[NML_HOST_MAX];
    int remote;         /* REMOTE: reached over the network, which OpenEMC does not serve */
    unsigned access;    /* NML_ACCESS_* */
    int server;
    double timeout_s;   /* negative = INF */
    int master;         /* 1: this process creates the buffer and removes it */
    int connection_number;
    int line;
} nml_process_cfg_t;

/* A parsed .nml file. */
typedef struct nml_config {
    char *path;
    int n_buffers;
    nml_buffer_cfg_t *buffers;
    int n_processes;
    nml_process_cfg_t *processes;
    int n_warnings;
    char **warnings;    /* "file:line: warning: ..." for ignored options */
} nml_config_t;

/* Parse a .nml file. NULL on error, err gets "file:line: what is wrong". */
nml_config_t *nml_config_load(const char *path, char *err, size_t errlen);
/* Free a parsed file (NULL is fine). */
void nml_config_free(nml_config_t *cfg);
/* The B line of buffer `name`, or NULL. */
const nml_buffer_cfg_t *nml_config_buffer(const nml_config_t *cfg, const char *name);
/* The P line of process for buffer (its own line, else its `default` line), or NULL. */
const nml_process_cfg_t *nml_config_process(const nml_config_t *cfg, const char *process,
                                            const char *buffer);
/* This instance's SysV key of a buffer: rtapi_instance_key(key), as HAL's keys. */
int nml_buffer_key(const nml_buffer_cfg_t *buffer);

/* ------------------------------------------------------------------ channels */

typedef struct nml_channel nml_channel_t;

/* Open buffer `buffer` as process `process` of the .nml file at path. A master process
 * (P line master 1) creates the buffer and removes it again in nml_close(); others attach.
 * NULL on failure with errno set (ENOENT: the buffer does not exist yet, i.e. no master
 * runs; EEXIST: another live master owns it; EINVAL: bad file or names; EPROTO: the
 * segment is not an OpenEMC buffer of this layout) and err filled with the reason. */
nml_channel_t *nml_open(const char *path, const char *buffer, const char *process, char *err,
                        size_t errlen);
/* The same with an already parsed file (the channel keeps no reference to cfg). */
nml_channel_t *nml_open_config(const nml_config_t *cfg, const char *buffer, const char *process,
                               char *err, size_t errlen);
/* Detach; a master also removes the segment it created. NULL is fine. */
void nml_close(nml_channel_t *ch);

/* Write msg (its header's size bytes). A `serial` buffer stamps serial_number with the
 * buffer's write counter, one sequence for all writers; *serial (may be NULL) gets it.
 * 0 on success, else -EACCES (no W access), -EINVAL (header size < 16), -EMSGSIZE (larger
 * than the buffer), -EAGAIN (queue full: nothing queued is lost, no serial is used),
 * -EBUSY (confirm_write: the last message is unread), -ESHUTDOWN (the master removed it). */
int nml_write(nml_channel_t *ch, const void *msg, int32_t *serial);
/* Queue: remove the oldest message into buf. Latest-value: copy the current message and
 * mark it read. Bytes copied, 0 when there is nothing (empty queue, never written),
 * -EACCES, -EMSGSIZE (cap too small; the message stays), -ESHUTDOWN, -EIO (corrupt). */
int nml_read(nml_channel_t *ch, void *buf, size_t cap);
/* As nml_read without removing or marking anything. */
int nml_peek(nml_channel_t *ch, void *buf, size_t cap);

/* Counter that changes on every write and every queued read of the buffer. */
uint32_t nml_change_count(const nml_channel_t *ch);
/* Sleep until the change counter differs from `seen` (no polling: a futex in the
 * buffer). 0 when it changed, -ETIMEDOUT, -EINTR, -ESHUTDOWN. timeout_ns < 0 = forever. */
int nml_wait_change(nml_channel_t *ch, uint32_t seen, int64_t timeout_ns);

/* Messages waiting in a queue (0 for a latest-value buffer). */
int nml_queue_count(const nml_channel_t *ch);
/* Successful writes so far (= the last serial handed out). */
uint64_t nml_write_count(const nml_channel_t *ch);
/* Write count of the message the last nml_read/nml_peek of this channel copied. */
uint64_t nml_last_read_count(const nml_channel_t *ch);
/* 1 while the buffer is alive, 0 once its master removed it (reopen to reattach). */
int nml_alive(const nml_channel_t *ch);
/* The B line, the P line and the largest message the buffer takes. */
const nml_buffer_cfg_t *nml_channel_buffer(const nml_channel_t *ch);
const nml_process_cfg_t *nml_channel_process(const nml_channel_t *ch);
size_t nml_max_message(const nml_channel_t *ch);

#ifdef __cplusplus
}
#endif

#endif
