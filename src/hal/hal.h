/* hal.h: public C API of the HAL library (LinuxCNC-compatible names, spec/hal.md §14). */
#ifndef HAL_H
#define HAL_H

#include <stdbool.h>
#include <stdint.h>
#include <stddef.h>
#include <signal.h>
#include "rtapi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- limits and lock levels ------------------------------------------- */
#define HAL_NAME_LEN 55           /* max characters in any HAL name */
#define HAL_LOCK_NONE 0           /* nothing locked */
#define HAL_LOCK_LOAD 1           /* loading components, pin/param/funct creation */
#define HAL_LOCK_CONFIG 2         /* signals, links, aliases, threads, addf */
#define HAL_LOCK_PARAMS 4         /* hal_param_set() */
#define HAL_LOCK_RUN 8            /* start/stop threads */
#define HAL_LOCK_TUNE (HAL_LOCK_LOAD | HAL_LOCK_CONFIG)
#define HAL_LOCK_ALL 255

#define HAL_STREAM_MAX_PINS 21    /* max fields per stream record */

/* ---- types ---------------------------------------------------------------- */
typedef enum {
    HAL_TYPE_UNSPECIFIED = -1,
    HAL_TYPE_UNINITIALIZED = 0,
    HAL_BIT = 1,
    HAL_FLOAT = 2,
    HAL_S32 = 3,
    HAL_U32 = 4,
    HAL_PORT = 5,
    HAL_S64 = 6,
    HAL_U64 = 7,
} hal_type_t;

typedef enum {
    HAL_DIR_UNSPECIFIED = -1,
    HAL_IN = 16,
    HAL_OUT = 32,
    HAL_IO = (HAL_IN | HAL_OUT),
} hal_pin_dir_t;

typedef enum {
    HAL_RO = 64,
    HAL_RW = 192,
} hal_param_dir_t;

typedef double real_t;
typedef volatile bool hal_bit_t;
typedef volatile int32_t hal_s32_t;
typedef volatile uint32_t hal_u32_t;
typedef volatile int64_t hal_s64_t;
typedef volatile uint64_t hal_u64_t;
typedef volatile real_t hal_float_t;
typedef volatile int hal_port_t;  /* handle = shm offset of the port ring, 0 = none */

/* new-API aliases of the value types */
typedef hal_bit_t hal_bool;
typedef hal_s32_t hal_si32;
typedef hal_u32_t hal_ui32;
typedef hal_s64_t hal_sint;
typedef hal_u64_t hal_uint;
typedef hal_float_t hal_real;

/* one 8-byte value cell of any HAL type (little-endian, low bytes used) */
typedef union {
    hal_bit_t b;
    hal_s32_t s;
    hal_u32_t u;
    hal_float_t f;
    hal_port_t p;
    hal_s64_t ls;
    hal_u64_t lu;
} hal_data_u;

/* ---- general ---------------------------------------------------------------- */
/* Create a component; returns its id (>0) or a negative errno. */
extern int hal_init(const char *name);
/* Remove a component with its pins, params and functs. */
extern int hal_exit(int comp_id);
/* Mark a component ready (no more pins/params/functs). */
extern int hal_ready(int comp_id);
/* Make a ready component initializing again; error if already unready. */
extern int hal_unready(int comp_id);
/* Make a component initializing again; no error if already unready. */
extern int hal_set_unready(int comp_id);
/* Map HAL memory without creating a component (costs one id once). */
extern int hal_lib_init(void);
/* Undo hal_lib_init when no component of this process remains. */
extern void hal_lib_exit(void);
/* Allocate never-freed memory inside the HAL block (8/16-byte aligned). */
extern void *hal_malloc(long int size);
/* Name of a component of this process, or NULL. */
extern const char *hal_comp_name(int comp_id);
/* Non-zero when this process has HAL memory mapped. */
extern int hal_is_init(void);
/* Text for a negative HAL error code. */
extern const char *hal_strerror(int errnum);
/* The RTAPI realtime type (rtapi.md §5). */
extern int hal_get_realtime_type(void);
/* Set the lock bits (HAL_LOCK_*). */
extern int hal_set_lock(unsigned char lock_type);
/* Current lock bits. */
extern unsigned char hal_get_lock(void);

/* ---- pins ------------------------------------------------------------------- */
extern int hal_pin_bit_new(const char *name, hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id);
extern int hal_pin_float_new(const char *name, hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id);
extern int hal_pin_u32_new(const char *name, hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id);
extern int hal_pin_s32_new(const char *name, hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id);
extern int hal_pin_u64_new(const char *name, hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id);
extern int hal_pin_s64_new(const char *name, hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id);
extern int hal_pin_port_new(const char *name, hal_pin_dir_t dir, hal_port_t **data_ptr_addr, int comp_id);

extern int hal_pin_bit_newf(hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_float_newf(hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_u32_newf(hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_s32_newf(hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_u64_newf(hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_s64_newf(hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_pin_port_newf(hal_pin_dir_t dir, hal_port_t **data_ptr_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Generic pin creation; data_ptr_addr must lie in HAL memory (hal_malloc). */
extern int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id);

/* New API: HAL allocates the pointer cell, stores its address in *ref and
 * sets the pin's start value to dflt.  Read/write with hal_get_/hal_set_<type>(*ref). */
extern int hal_pin_new_bool(int comp_id, hal_pin_dir_t dir, hal_bit_t ***ref, bool dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_si32(int comp_id, hal_pin_dir_t dir, hal_s32_t ***ref, int32_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_ui32(int comp_id, hal_pin_dir_t dir, hal_u32_t ***ref, uint32_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_sint(int comp_id, hal_pin_dir_t dir, hal_s64_t ***ref, int64_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_uint(int comp_id, hal_pin_dir_t dir, hal_u64_t ***ref, uint64_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_real(int comp_id, hal_pin_dir_t dir, hal_float_t ***ref, real_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_pin_new_port(int comp_id, hal_pin_dir_t dir, hal_port_t ***ref, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Give pin `pin_name` the name `alias` (NULL restores the original). */
extern int hal_pin_alias(const char *pin_name, const char *alias);

/* ---- parameters ----------------------------------------------------------- */
extern int hal_param_bit_new(const char *name, hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id);
extern int hal_param_float_new(const char *name, hal_param_dir_t dir, hal_float_t *data_addr, int comp_id);
extern int hal_param_u32_new(const char *name, hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id);
extern int hal_param_s32_new(const char *name, hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id);
extern int hal_param_u64_new(const char *name, hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id);
extern int hal_param_s64_new(const char *name, hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id);

extern int hal_param_bit_newf(hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_param_float_newf(hal_param_dir_t dir, hal_float_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_param_u32_newf(hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_param_s32_newf(hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_param_u64_newf(hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
extern int hal_param_s64_newf(hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* Generic param creation; data_addr must lie in HAL memory. */
extern int hal_param_new(const char *name, hal_type_t type, hal_param_dir_t dir, void *data_addr, int comp_id);

/* New API: HAL allocates the value cell (set to dflt) and stores its address in *ref. */
extern int hal_param_new_bool(int comp_id, hal_param_dir_t dir, hal_bit_t **ref, bool dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_param_new_si32(int comp_id, hal_param_dir_t dir, hal_s32_t **ref, int32_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_param_new_ui32(int comp_id, hal_param_dir_t dir, hal_u32_t **ref, uint32_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_param_new_sint(int comp_id, hal_param_dir_t dir, hal_s64_t **ref, int64_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_param_new_uint(int comp_id, hal_param_dir_t dir, hal_u64_t **ref, uint64_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
extern int hal_param_new_real(int comp_id, hal_param_dir_t dir, hal_float_t **ref, real_t dflt, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* Param setters by name (blocked only by HAL_LOCK_PARAMS). */
extern int hal_param_bit_set(const char *name, int value);
extern int hal_param_float_set(const char *name, double value);
extern int hal_param_u32_set(const char *name, unsigned long value);
extern int hal_param_s32_set(const char *name, signed long value);
extern int hal_param_u64_set(const char *name, uint64_t value);
extern int hal_param_s64_set(const char *name, int64_t value);
extern int hal_param_set(const char *name, hal_type_t type, void *value_addr);
/* Give param `param_name` the name `alias` (NULL restores the original). */
extern int hal_param_alias(const char *param_name, const char *alias);

/* ---- signals -------------------------------------------------------------- */
extern int hal_signal_new(const char *name, hal_type_t type);
extern int hal_signal_delete(const char *name);
extern int hal_link(const char *pin_name, const char *sig_name);
extern int hal_unlink(const char *pin_name);

/* ---- functions and threads ------------------------------------------------ */
typedef int (*hal_constructor_t)(char *prefix, char *arg);
typedef hal_constructor_t constructor;

extern int hal_export_funct(const char *name, void (*funct)(void *, long), void *arg,
                            int uses_fp, int reentrant, int comp_id);
extern int hal_export_functf(void (*funct)(void *, long), void *arg, int uses_fp,
                             int reentrant, int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
extern int hal_create_thread(const char *name, unsigned long period_nsec, int uses_fp);
extern int hal_thread_delete(const char *name);
extern int hal_add_funct_to_thread(const char *funct_name, const char *thread_name, int position);
extern int hal_init_funct_to_thread(const char *funct_name, const char *thread_name, int position);
extern int hal_del_funct_from_thread(const char *funct_name, const char *thread_name);
extern int hal_start_threads(void);
extern int hal_stop_threads(void);
extern int hal_set_constructor(int comp_id, hal_constructor_t make);
/* rtapi_app's `newinst comp name [args]`: call comp's constructor with prefix `name`
 * and the args joined by spaces (-ENOENT unknown comp, -ENOEXEC no constructor). */
extern int hal_newinst(const char *comp_name, const char *inst_name, int argc,
                       const char **argv);
/* Use the next base period exactly as requested (setexact_for_test_suite_only);
 * silent; -EBUSY once a thread exists (caller prints the HAL_LIB texts). */
extern int hal_set_exact_period(void);

/* ---- ports (byte FIFOs owned by port signals) ------------------------------ */
extern int hal_port_alloc(unsigned size, hal_port_t *port);
extern bool hal_port_read(const hal_port_t *port, char *dest, unsigned count);
extern bool hal_port_peek(const hal_port_t *port, char *dest, unsigned count);
extern bool hal_port_peek_commit(const hal_port_t *port, unsigned count);
extern bool hal_port_write(const hal_port_t *port, const char *src, unsigned count);
extern unsigned hal_port_readable(const hal_port_t *port);
extern unsigned hal_port_writable(const hal_port_t *port);
extern unsigned hal_port_buffer_size(const hal_port_t *port);
extern void hal_port_clear(const hal_port_t *port);
#ifdef ULAPI
/* Sleep-poll until `count` bytes are readable/writable or *stop is set. */
extern void hal_port_wait_readable(hal_port_t **port, unsigned count, sig_atomic_t *stop);
extern void hal_port_wait_writable(hal_port_t **port, unsigned count, sig_atomic_t *stop);
#endif

/* ---- streams (lock-free record FIFOs in their own shm segment) ------------- */
union hal_stream_data {
    real_t f;
    bool b;
    int32_t s;
    uint32_t u;
    int64_t l;
    uint64_t k;
};

struct hal_stream_shm;
typedef struct {
    int comp_id;                 /* owner passed to create/attach */
    int shmem_id;                /* SysV shm id of the segment */
    struct hal_stream_shm *fifo; /* mapped segment */
} hal_stream_t;

/* key is the base key (the instance is applied inside); a stream of depth D holds
 * D-1 records; read -> 0 or -EAGAIN when empty (underrun counted); write -> 0 or
 * -ENOSPC when full (overrun counted, sample number not used up); depth = records
 * queued now; maxdepth = the creation depth D; typestring letters f/r b s u l k. */
extern int hal_stream_create(hal_stream_t *stream, int comp_id, int key, int depth, const char *typestring);
extern void hal_stream_destroy(hal_stream_t *stream);
extern int hal_stream_attach(hal_stream_t *stream, int comp_id, int key, const char *typestring);
extern int hal_stream_detach(hal_stream_t *stream);
extern int hal_stream_element_count(hal_stream_t *stream);
extern hal_type_t hal_stream_element_type(hal_stream_t *stream, int idx);
extern int hal_stream_read(hal_stream_t *stream, union hal_stream_data *buf, unsigned *sampleno);
extern bool hal_stream_readable(hal_stream_t *stream);
extern int hal_stream_depth(hal_stream_t *stream);
extern int hal_stream_maxdepth(hal_stream_t *stream);
extern int hal_stream_num_underruns(hal_stream_t *stream);
extern int hal_stream_num_overruns(hal_stream_t *stream);
extern int hal_stream_write(hal_stream_t *stream, union hal_stream_data *buf);
extern bool hal_stream_writable(hal_stream_t *stream);
#ifdef ULAPI
extern void hal_stream_wait_writable(hal_stream_t *stream, sig_atomic_t *stop);
extern void hal_stream_wait_readable(hal_stream_t *stream, sig_atomic_t *stop);
#endif

/* ---- lookup / master query API (user side) --------------------------------- */
/* Value and type of a pin by name (alias or original); connected = linked. */
extern int hal_get_pin_value_by_name(const char *name, hal_type_t *type, hal_data_u **data, bool *connected);
/* Value and type of a signal; has_writers = an OUT pin is linked. */
extern int hal_get_signal_value_by_name(const char *name, hal_type_t *type, hal_data_u **data, bool *has_writers);
/* Value and type of a param by name (alias or original). */
extern int hal_get_param_value_by_name(const char *name, hal_type_t *type, hal_data_u **data);

/* Pin-or-param (pins first): type, dir (HAL_IN/OUT/IO for pins, HAL_RO/RW for
 * params) and a copy of the current value; -ENOENT if neither exists. */
extern int hal_get_p(const char *name, hal_type_t *type, int *dir, hal_data_u *value);
/* Write a pin-or-param (pins first) as setp does: -ENOENT, -EACCES (OUT pin,
 * linked pin, RO param), -EBADF (port or type differs from the object's). */
extern int hal_set_p(const char *name, hal_type_t type, const hal_data_u *value);
/* Signal: type, copy of the value (port: buffer size in value->u), writers count. */
extern int hal_get_s(const char *name, hal_type_t *type, hal_data_u *value, int *writers);
/* Write a signal as sets does: -ENOENT, -EACCES (has OUT pin), -EBADF (type);
 * for a port signal value->u is the buffer size, 1..65536 (-EISCONN if allocated;
 * writers do not block it). */
extern int hal_set_s(const char *name, hal_type_t type, const hal_data_u *value);
/* Address (in this process) of a pin's/param's current value cell, or NULL. */
extern hal_data_u *hal_getref_p(const char *name, hal_type_t *type);
/* Address (in this process) of a signal's value cell, or NULL. */
extern hal_data_u *hal_getref_s(const char *name, hal_type_t *type);

/* Callback per listed object; return non-zero to stop the walk. */
typedef int (*hal_list_cb_t)(const char *name, hal_type_t type, int dir, void *ctx);
/* Walk pins (list order), calling cb(name, type, pin dir). */
extern int hal_list_p(hal_list_cb_t cb, void *ctx);
/* Walk params (list order), calling cb(name, type, param dir). */
extern int hal_list_p_s(hal_list_cb_t cb, void *ctx);
/* Walk signals (list order), calling cb(name, type, 0). */
extern int hal_list_s(hal_list_cb_t cb, void *ctx);
/* Walk comps newest first, calling cb(name, 0, comp_id). */
extern int hal_list_comp(hal_list_cb_t cb, void *ctx);
/* Walk functs (list order), calling cb(name, 0, users). */
extern int hal_list_funct(hal_list_cb_t cb, void *ctx);
/* Walk threads newest first, calling cb(name, 0, 0). */
extern int hal_list_thread(hal_list_cb_t cb, void *ctx);

/* Public facts about one component. */
typedef struct {
    int comp_id;
    int type;       /* HAL_COMP_RT / HAL_COMP_USER / HAL_COMP_INST (hal_priv.h) */
    int ready;      /* non-zero once hal_ready was called */
    int pid;        /* user comps: owner pid, RT: 0 */
    int owner_alive; /* user comps: 0 once the owner process is gone (killed); RT: 1 */
    char name[HAL_NAME_LEN + 1];
} hal_comp_info_t;
/* Look a component up by name / id; 0 or -ENOENT. */
extern int hal_comp_by_name(const char *name, hal_comp_info_t *info);
extern int hal_comp_by_id(int comp_id, hal_comp_info_t *info);
/* Remove a user component whose process no longer exists (0), else -ENOENT (no such
   component), -EINVAL (not a user component) or -EBUSY (its process still runs). */
extern int hal_comp_remove_orphan(const char *name);

/* Object counts and memory use (halcmd status mem). */
typedef struct {
    long mem_used, mem_total;
    int comps_active, comps_recycled;
    int pins_active, pins_recycled;
    int params_active, params_recycled;
    int aliases_active, aliases_recycled;
    int sigs_active, sigs_recycled;
    int functs_active, functs_recycled;
    int threads_active, threads_recycled;
} hal_stats_t;
extern int hal_statistics(hal_stats_t *stats);

/* ---- inline helpers ---------------------------------------------------------- */
/* Extend an nbits-wide wrapping counter reading to 64 bits given the old value. */
static inline int64_t hal_extend_counter(int64_t old, int64_t newlow, int nbits)
{
    int64_t mask = (nbits >= 64) ? -1 : (((int64_t)1 << nbits) - 1);
    int64_t half = (nbits >= 64) ? 0 : ((int64_t)1 << (nbits - 1));
    int64_t diff = (newlow - old) & mask;
    if (nbits < 64 && diff >= half)
        diff -= mask + 1;
    return old + diff;
}

/* new-API accessors: ref is the pointer cell handed out by hal_pin_new_<type> */
static inline bool hal_get_bool(hal_bit_t *const *ref) { return **ref; }
static inline void hal_set_bool(hal_bit_t *const *ref, bool v) { **ref = v; }
static inline int32_t hal_get_si32(hal_s32_t *const *ref) { return **ref; }
static inline void hal_set_si32(hal_s32_t *const *ref, int32_t v) { **ref = v; }
static inline uint32_t hal_get_ui32(hal_u32_t *const *ref) { return **ref; }
static inline void hal_set_ui32(hal_u32_t *const *ref, uint32_t v) { **ref = v; }
static inline int64_t hal_get_sint(hal_s64_t *const *ref) { return **ref; }
static inline void hal_set_sint(hal_s64_t *const *ref, int64_t v) { **ref = v; }
static inline uint64_t hal_get_uint(hal_u64_t *const *ref) { return **ref; }
static inline void hal_set_uint(hal_u64_t *const *ref, uint64_t v) { **ref = v; }
static inline real_t hal_get_real(hal_float_t *const *ref) { return **ref; }
static inline void hal_set_real(hal_float_t *const *ref, real_t v) { **ref = v; }

#ifdef __cplusplus
}
#endif
#endif
