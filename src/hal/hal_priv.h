/* hal_priv.h: HAL shared-memory layout, list walking, lookup and locking for HAL tools. */
#ifndef HAL_PRIV_H
#define HAL_PRIV_H

/*
 * The HAL block is one SysV segment (key rtapi_instance_key(0x48414C32)),
 * size $OPENEMC_HAL_SIZE or 32 MiB, mapped at a different address in every
 * process.  Objects refer to each other by OFFSETS from the block start
 * (0 = none); convert with SHMPTR(off) / SHMOFF(ptr).  hal_data (the header)
 * sits at offset 0.
 *
 * Locking: take the recursive HAL mutex with halpr_mutex_get() and release it
 * with halpr_mutex_give() around every walk or change; the realtime cycle
 * never takes it (only once, after a thread's init cycle, does the thread
 * free its executed init list under halpr_mutex_try(), retrying on later
 * cycles while the mutex is busy).  A process that dies holding the mutex is
 * detected and the mutex is taken over.
 *
 * Walking the lists in the order listings need (spec/hal.md §1):
 *   comps   newest first:  for (c = halpr_first_comp(); c; c = halpr_next_comp(c))
 *   pins    strcmp order:  for (p = halpr_first_pin(); p; p = halpr_next_pin(p))
 *   params  strcmp order:  halpr_first_param / halpr_next_param
 *   signals strcmp order:  halpr_first_sig / halpr_next_sig
 *   functs  strcmp order:  halpr_first_funct / halpr_next_funct
 *   threads newest first (= slowest first): halpr_first_thread / halpr_next_thread
 *   pins of one signal, strcmp order: halpr_first_sig_pin(sig) / halpr_next_sig_pin(pin)
 *   functs of a thread, run order:     halpr_first_entry(thread->funct_list) / halpr_next_entry(e)
 *   pending init functs of a thread:   halpr_first_entry(thread->init_list) / halpr_next_entry(e)
 *   aliased pins / params:  walk pins/params and test pin->oldname != 0;
 *                           halpr_original_name(pin->oldname) gives the original
 * Names in lists are the current names (alias when aliased); the lists are
 * re-sorted when an alias is set.  halpr_find_*_by_name also accept the
 * original name of an aliased pin/param.
 *
 * Pointers stored in shm for the realtime side (funct code/arg, funct-entry
 * caches, thread time cells) are addresses in the rtapi_app process: only
 * ever dereference them there.  A pin's pointer cell holds an address in the
 * OWNER's process: owner_comp->shmem_base + offset of the value cell.
 *
 * Component ids (hal.md §4): every rtapi_init() costs one id.  The first
 * hal_init()/hal_lib_init() of a user process attaches the library (+1), each
 * hal_init adds +1.  LinuxCNC's halcmd detaches and re-attaches around every
 * fork (loadrt, loadusr, unloadrt, ...): call hal_reattach_for_fork(comp_id)
 * in the parent before forking; it costs exactly +2 ids, moves the component
 * to the head of the comp list (as a fresh hal_init would) and returns the
 * component's NEW id (use it from then on).
 *
 * Threads exist only in rtapi_app.  Each has a pseudo comp __<name>
 * (is_thread_comp) owning <name>.time/.tmax/.threadbeat; when the RT comp
 * that created threads (e.g. `threads`) exits, those pseudo comps go too,
 * while the threads keep running until hal_lib is unloaded (hal.md §8).
 *
 * halcmd after a successful loadrt stores the args with halpr_set_insmod_args().
 */

#include "hal.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HAL_DATA_VERSION 0x4f450016          /* must match or attach fails (-EPROTO) */
#define HAL_DEFAULT_SIZE (32L * 1024 * 1024)   /* arena size without $OPENEMC_HAL_SIZE */
#define HAL_MIN_SIZE (256L * 1024)             /* smallest accepted $OPENEMC_HAL_SIZE */

extern char *hal_shmem_base;                 /* this process's address of the block */
extern struct hal_data *hal_data;            /* the header at offset 0 */

#define SHMPTR(off) ((void *)(hal_shmem_base + (off)))
#define SHMOFF(ptr) ((int)((char *)(ptr) - hal_shmem_base))
#define SHMCHK(ptr) (((char *)(ptr)) > hal_shmem_base && \
                     ((char *)(ptr)) < hal_shmem_base + hal_data->shmem_size)

/* recursive cross-process mutex living in the block */
typedef struct {
    volatile int owner_tid;    /* kernel tid of the holder, 0 = free */
    volatile int owner_pid;    /* pid of the holder (dead-holder detection) */
    int depth;                 /* recursion depth of the holder */
} hal_mutex_t;

/* component kinds (hal_comp_info_t.type, hal_comp_t.type) */
typedef enum {
    HAL_COMP_RT = 0,     /* created inside rtapi_app */
    HAL_COMP_USER = 1,   /* created by another process; pid recorded */
    HAL_COMP_INST = 2,   /* instance record (unused) */
} hal_comp_type_t;

/* object kinds: free lists and statistics */
enum {
    HAL_KIND_COMP, HAL_KIND_PIN, HAL_KIND_PARAM, HAL_KIND_ALIAS, HAL_KIND_SIG,
    HAL_KIND_FUNCT, HAL_KIND_THREAD, HAL_KIND_ENTRY, HAL_KIND_COUNT
};

/* counters and free list of one object kind */
typedef struct {
    int active;      /* objects in use */
    int recycled;    /* objects on the free list */
    int free_ptr;    /* head of the free list (linked via the first int) */
} hal_kind_t;

/* a name index: sorted (or newest-first) list plus hash buckets */
typedef struct {
    int list_ptr;    /* first object in listing order */
    int hint_ptr;    /* last inserted object (speeds up sorted inserts) */
    int hash_ptr;    /* offset of int[nbuckets] hash chain heads */
    int nbuckets;    /* power of two */
} hal_index_t;

/* common head of every named object: list link, hash link, name */
#define HAL_NODE_FIELDS \
    int next_ptr;   /* next object in listing order (or free list) */ \
    int prev_ptr;   /* previous object in listing order */ \
    int hash_next;  /* next object in the same hash bucket */ \
    char name[HAL_NAME_LEN + 1]

typedef struct {
    HAL_NODE_FIELDS;
} hal_node_t;

/* the block header at offset 0 */
typedef struct hal_data {
    volatile int version;       /* HAL_DATA_VERSION, written last by the creator */
    int creator_pid;            /* process that created the block */
    long shmem_size;            /* bytes in the block */
    long shmem_used;            /* bump allocator: next free offset */
    hal_mutex_t mutex;          /* the HAL mutex */
    volatile unsigned char lock;/* HAL_LOCK_* bits */
    volatile int threads_running; /* start/stop flag read by every thread */
    long base_period;           /* ns, fixed by the first thread (0 = none yet) */
    int exact_base_period;      /* setexact_for_test_suite_only was given */
    int last_thread_prio;       /* priority of the newest thread */
    int thread_count;           /* threads ever created (for priorities) */
    hal_index_t comps;          /* newest first */
    hal_index_t pins;           /* strcmp order */
    hal_index_t params;         /* strcmp order */
    hal_index_t sigs;           /* strcmp order */
    hal_index_t functs;         /* strcmp order */
    hal_index_t threads;        /* newest first */
    int pin_alias_list;         /* hal_oldname_t of aliased pins */
    int param_alias_list;       /* hal_oldname_t of aliased params */
    hal_kind_t kinds[HAL_KIND_COUNT];
} hal_data_t;

/* a component */
typedef struct {
    HAL_NODE_FIELDS;
    int comp_id;                /* rtapi id shown by `show comp` */
    int type;                   /* hal_comp_type_t */
    volatile int ready;         /* 0 initializing, 1 ready */
    int pid;                    /* owner pid (user comps), 0 for RT */
    unsigned long long owner_start; /* owner's start time (clock ticks after boot), 0 unknown */
    int insmod_args;            /* offset of saved loadrt args, 0 = none */
    int is_thread_comp;         /* pseudo comp __<thread> */
    char *shmem_base;           /* block address in the owner's process */
    hal_constructor_t make;     /* owner-process constructor, or NULL */
} hal_comp_t;

/* the original name of an aliased pin/param */
typedef struct {
    int next_ptr;               /* next alias record (or free list) */
    int obj_ptr;                /* the aliased pin/param */
    char name[HAL_NAME_LEN + 1];/* original name */
} hal_oldname_t;

/* a pin */
typedef struct {
    HAL_NODE_FIELDS;
    int data_ptr_addr;          /* offset of the owner's pointer cell */
    int owner_ptr;              /* offset of the owning hal_comp_t */
    int signal;                 /* offset of the linked hal_sig_t, 0 = none */
    int sig_next;               /* next pin on the same signal (name order) */
    int oldname;                /* offset of hal_oldname_t when aliased */
    hal_type_t type;
    hal_pin_dir_t dir;
    hal_data_u dummysig;        /* value cell used while unlinked */
} hal_pin_t;

/* a parameter */
typedef struct {
    HAL_NODE_FIELDS;
    int data_ptr;               /* offset of the value storage */
    int owner_ptr;              /* offset of the owning hal_comp_t */
    int oldname;                /* offset of hal_oldname_t when aliased */
    hal_type_t type;
    hal_param_dir_t dir;
} hal_param_t;

/* a signal */
typedef struct {
    HAL_NODE_FIELDS;
    int data_ptr;               /* offset of the 8-byte value cell */
    hal_type_t type;
    int readers;                /* IN and IO pins */
    int writers;                /* OUT pins */
    int bidirs;                 /* IO pins */
    int pins_ptr;               /* first linked pin, name order, via sig_next */
    hal_data_u value;           /* the value cell (data_ptr points here) */
} hal_sig_t;

/* the timing cells of one funct that the cycle updates, together in one
   16-byte-aligned block (one cache line): <funct>.time's pointer cell and the
   storage of <funct>.tmax and <funct>.tmax-increased */
typedef struct {
    hal_s32_t *time;            /* RT: pointer cell of the <funct>.time pin */
    hal_s32_t tmax;             /* <funct>.tmax */
    hal_bit_t tmax_increased;   /* <funct>.tmax-increased */
} hal_funct_timing_t;

/* an exported function */
typedef struct {
    HAL_NODE_FIELDS;
    int uses_fp;
    int reentrant;
    int users;                  /* thread entries (cyclic + init) using it */
    int owner_ptr;              /* offset of the owning hal_comp_t */
    void *arg;                  /* RT-process address */
    void (*funct)(void *, long);/* RT-process address */
    hal_funct_timing_t *timing; /* RT address of its timing cells */
} hal_funct_t;

/* one function slot in a thread, 32 bytes on a 32-byte boundary so the fields
   the realtime cycle reads share one cache line */
typedef struct {
    void (*funct)(void *, long);/* cached from the funct (RT address) */
    void *arg;
    hal_funct_timing_t *timing;
    int next_ptr;               /* next entry in run order */
    int funct_ptr;              /* offset of hal_funct_t */
} hal_funct_entry_t;

/* a realtime thread */
typedef struct {
    HAL_NODE_FIELDS;
    int uses_fp;
    long period;                /* nominal period, ns */
    int priority;
    int task_id;                /* rtapi task */
    int comp_ptr;               /* offset of the pseudo comp __<name>, 0 once gone */
    int funct_list;             /* first hal_funct_entry_t of the cycle */
    int init_list;              /* pending init functs, run once by the init cycle */
    volatile int init_done;     /* init cycle has run */
    volatile int init_reap;     /* init list still to be freed (RT try-locks) */
    hal_s32_t **runtime;        /* RT addresses of <thread>.time/.tmax/.threadbeat */
    hal_s32_t *maxtime;
    hal_s64_t **threadbeat;
    hal_s32_t *scratch_s32_ptr; /* RT: parks runtime when the pseudo comp is gone */
    hal_s64_t *scratch_s64_ptr; /* RT: parks threadbeat likewise */
    hal_data_u scratch[3];      /* cells behind the scratch pointers */
    int creator_id;             /* comp whose rtapi_app_main created it; its
                                   hal_exit removes the pseudo comp */
    volatile int in_cycle;      /* the task is running functs right now */
    volatile unsigned cycle_seq;/* bumped after every pass that ran functs */
} hal_thread_t;

/* ---- locking ---- */
/* Take the recursive HAL mutex (spins, yields; takes over from dead holders). */
extern void halpr_mutex_get(void);
/* Release one level of the HAL mutex. */
extern void halpr_mutex_give(void);
/* Take the HAL mutex only if free right now; 1 on success (never waits). */
extern int halpr_mutex_try(void);

/* ---- lookup (call with the mutex held) ---- */
extern hal_comp_t *halpr_find_comp_by_name(const char *name);
extern hal_comp_t *halpr_find_comp_by_id(int id);
extern hal_pin_t *halpr_find_pin_by_name(const char *name);
extern hal_param_t *halpr_find_param_by_name(const char *name);
extern hal_sig_t *halpr_find_sig_by_name(const char *name);
extern hal_funct_t *halpr_find_funct_by_name(const char *name);
extern hal_thread_t *halpr_find_thread_by_name(const char *name);
/* Next pin after `start` (NULL = from the beginning) owned by comp. */
extern hal_pin_t *halpr_find_pin_by_owner(hal_comp_t *owner, hal_pin_t *start);
/* Next param after `start` owned by comp. */
extern hal_param_t *halpr_find_param_by_owner(hal_comp_t *owner, hal_param_t *start);
/* Next funct after `start` owned by comp. */
extern hal_funct_t *halpr_find_funct_by_owner(hal_comp_t *owner, hal_funct_t *start);

/* Store the loadrt argument string of a component (for `save`). */
extern int halpr_set_insmod_args(const char *comp_name, const char *args);
/* Saved loadrt args of a component, or NULL when none were stored. */
static inline const char *halpr_insmod_args(const hal_comp_t *c)
{
    return c->insmod_args ? (const char *)SHMPTR(c->insmod_args) : NULL;
}
/* Original name behind an oldname offset. */
static inline const char *halpr_original_name(int oldname)
{
    return ((hal_oldname_t *)SHMPTR(oldname))->name;
}
/* Owner of a pin/param/funct (pass its owner_ptr). */
static inline hal_comp_t *halpr_owner(int owner_ptr)
{
    return (hal_comp_t *)SHMPTR(owner_ptr);
}
/* The value cell a pin currently reads/writes, in this process. */
static inline hal_data_u *halpr_pin_value(hal_pin_t *pin)
{
    if (pin->signal)
        return (hal_data_u *)SHMPTR(((hal_sig_t *)SHMPTR(pin->signal))->data_ptr);
    return &pin->dummysig;
}
/* The value cell of a signal / param, in this process. */
static inline hal_data_u *halpr_sig_value(hal_sig_t *sig)
{
    return (hal_data_u *)SHMPTR(sig->data_ptr);
}
static inline hal_data_u *halpr_param_value(hal_param_t *param)
{
    return (hal_data_u *)SHMPTR(param->data_ptr);
}

/* Costs +2 ids like LinuxCNC's detach/re-attach around fork; returns the new id. */
extern int hal_reattach_for_fork(int comp_id);

/* ---- iteration helpers (call with the mutex held) ---- */
#define HALPR_AT(type, off) ((off) ? (type *)SHMPTR(off) : (type *)0)
static inline hal_comp_t *halpr_first_comp(void) { return HALPR_AT(hal_comp_t, hal_data->comps.list_ptr); }
static inline hal_comp_t *halpr_next_comp(hal_comp_t *c) { return HALPR_AT(hal_comp_t, c->next_ptr); }
static inline hal_pin_t *halpr_first_pin(void) { return HALPR_AT(hal_pin_t, hal_data->pins.list_ptr); }
static inline hal_pin_t *halpr_next_pin(hal_pin_t *p) { return HALPR_AT(hal_pin_t, p->next_ptr); }
static inline hal_param_t *halpr_first_param(void) { return HALPR_AT(hal_param_t, hal_data->params.list_ptr); }
static inline hal_param_t *halpr_next_param(hal_param_t *p) { return HALPR_AT(hal_param_t, p->next_ptr); }
static inline hal_sig_t *halpr_first_sig(void) { return HALPR_AT(hal_sig_t, hal_data->sigs.list_ptr); }
static inline hal_sig_t *halpr_next_sig(hal_sig_t *s) { return HALPR_AT(hal_sig_t, s->next_ptr); }
static inline hal_funct_t *halpr_first_funct(void) { return HALPR_AT(hal_funct_t, hal_data->functs.list_ptr); }
static inline hal_funct_t *halpr_next_funct(hal_funct_t *f) { return HALPR_AT(hal_funct_t, f->next_ptr); }
static inline hal_thread_t *halpr_first_thread(void) { return HALPR_AT(hal_thread_t, hal_data->threads.list_ptr); }
static inline hal_thread_t *halpr_next_thread(hal_thread_t *t) { return HALPR_AT(hal_thread_t, t->next_ptr); }
static inline hal_pin_t *halpr_first_sig_pin(hal_sig_t *s) { return HALPR_AT(hal_pin_t, s->pins_ptr); }
static inline hal_pin_t *halpr_next_sig_pin(hal_pin_t *p) { return HALPR_AT(hal_pin_t, p->sig_next); }
static inline hal_funct_entry_t *halpr_first_entry(int list) { return HALPR_AT(hal_funct_entry_t, list); }
static inline hal_funct_entry_t *halpr_next_entry(hal_funct_entry_t *e) { return HALPR_AT(hal_funct_entry_t, e->next_ptr); }
/* The funct behind a thread entry. */
static inline hal_funct_t *halpr_entry_funct(hal_funct_entry_t *e) { return (hal_funct_t *)SHMPTR(e->funct_ptr); }

/* ---- realtime side (used by rtlib/hal_lib.so inside rtapi_app) ---- */
/* Attach/create the block as the RT process (costs id 1 on a fresh instance). */
extern int hal_rt_startup(void);
/* Stop and delete all threads, then detach (hal_lib's rtapi_app_exit). */
extern void hal_rt_shutdown(void);

#ifdef __cplusplus
}
#endif
#endif
