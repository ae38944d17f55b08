/* rtapi.h: the RTAPI C API (uspace) shared by realtime modules and user programs. */
#ifndef RTAPI_H
#define RTAPI_H

#include <stdarg.h>
#include <stddef.h>
#include <sys/types.h>
#include <spawn.h>
#include "rtapi_errno.h"

#ifdef __cplusplus
#define RTAPI_BEGIN_DECLS extern "C" {
#define RTAPI_END_DECLS }
#else
#define RTAPI_BEGIN_DECLS
#define RTAPI_END_DECLS
#endif

RTAPI_BEGIN_DECLS

#define RTAPI_NAME_LEN 31
#define RTAPI_MAX_MODULES 1024
#define RTAPI_MAX_TASKS 1024
#define RTAPI_MAX_SHMEMS 64
#define RTAPI_MIN_PERIOD_NS 1000   /* shortest task period accepted: no machine wakes a thread more often */
#define RTAPI_NO_FP 0
#define RTAPI_USES_FP 1

/* Symbol visibility used for everything a module must export. */
#define RTAPI_VISIBLE __attribute__((visibility("default")))

/* ---- modules and the component-id counter (hal.md §4) ---- */
/* Allocate the next id from this instance's global counter (first id is 1). */
int rtapi_init(const char *modname);
/* Release an id obtained from rtapi_init; detaches the counter when unused. */
int rtapi_exit(int module_id);

/* ---- messages ---- */
typedef enum {
    RTAPI_MSG_NONE = 0,
    RTAPI_MSG_ERR,
    RTAPI_MSG_WARN,
    RTAPI_MSG_INFO,
    RTAPI_MSG_DBG,
    RTAPI_MSG_ALL
} msg_level_t;

typedef void (*rtapi_msg_handler_t)(msg_level_t level, const char *fmt, va_list ap);

/* Print always, to stdout. */
void rtapi_print(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Print when level <= the current level (stderr; RTAPI_MSG_ALL to stdout). */
void rtapi_print_msg(msg_level_t level, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
int rtapi_set_msg_level(int level);
int rtapi_get_msg_level(void);
/* Replace the output sink; NULL restores the default one. */
void rtapi_set_msg_handler(rtapi_msg_handler_t handler);
rtapi_msg_handler_t rtapi_get_msg_handler(void);
int rtapi_snprintf(char *buf, unsigned long size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int rtapi_vsnprintf(char *buf, unsigned long size, const char *fmt, va_list ap);

/* ---- clock and time (all in ns) ---- */
long int rtapi_clock_set_period(long int nsecs);
void rtapi_delay(long int nsec);
long int rtapi_delay_max(void);
long long int rtapi_get_time(void);
long long int rtapi_get_clocks(void);

/* ---- tasks ---- */
int rtapi_prio_highest(void);
int rtapi_prio_lowest(void);
int rtapi_prio_next_higher(int prio);
int rtapi_prio_next_lower(int prio);
/* Create a task (not yet running); returns its id 0..RTAPI_MAX_TASKS-1. */
int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio, int owner,
                   unsigned long int stacksize, int uses_fp);
/* Stop (cancel at its next wait) and join a task, then free its slot. */
int rtapi_task_delete(int task_id);
/* Start the thread; taskcode runs at once and calls rtapi_wait() per period. */
int rtapi_task_start(int task_id, unsigned long int period_nsec);
/* Sleep until the start of the next period of the calling task. */
void rtapi_wait(void);
/* Hold a task at its next rtapi_wait() until resumed. */
int rtapi_task_pause(int task_id);
int rtapi_task_resume(int task_id);
/* Id of the calling task, or -EINVAL outside tasks. */
int rtapi_task_self(void);
/* Restart the calling task's period from now. */
int rtapi_task_self_resync(void);
/* Absolute time (ns, CLOCK_MONOTONIC) the calling task will next wake. */
long long rtapi_task_pll_get_reference(void);
/* Per-period correction in ns, clamped to +-1% of the period. */
int rtapi_task_pll_set_correction(long value);

/* Execution statistics of a task, kept by rtapi_wait() (HAL exports them). */
typedef struct {
    long long period_ns;        /* nominal period */
    unsigned long long cycles;  /* completed periods */
    unsigned long long overruns;/* deadlines already past when rtapi_wait ran */
    long long last_exec_ns;     /* time from last wake-up to the following wait */
    long long max_exec_ns;      /* max of last_exec_ns since start / reset */
    long long last_wake_ns;     /* lateness of the last wake-up vs its deadline */
    long long max_wake_ns;      /* max of last_wake_ns since start / reset */
} rtapi_task_stats_t;

/* Copy task_id's statistics into *stats. */
int rtapi_task_get_stats(int task_id, rtapi_task_stats_t *stats);
/* Reset the max_* fields of task_id's statistics. */
int rtapi_task_reset_stats(int task_id);

/* ---- shared memory (SysV); key is the BASE key, the instance is applied here ---- */
int rtapi_shmem_new(int key, int module_id, unsigned long int size);
int rtapi_shmem_delete(int shmem_id, int module_id);
int rtapi_shmem_getptr(int shmem_id, void **ptr);

/* ---- realtime capability ---- */
typedef enum {
    RTAPI_REALTIME_UNINITIALIZED = -1,
    RTAPI_REALTIME_NONE = 0,
    RTAPI_REALTIME_UNKNOWN_FIFO = 1,
    RTAPI_REALTIME_PREEMPT_DYNAMIC = 2,
    RTAPI_REALTIME_PREEMPT_RT = 3,
    RTAPI_REALTIME_RTAI = 4,
    RTAPI_REALTIME_LXRT = 5,
    RTAPI_REALTIME_XENOMAI = 6,
    RTAPI_REALTIME_XENOMAI_EVL = 7
} rtapi_realtime_type_t;

int rtapi_is_realtime(void);
int rtapi_is_kernelspace(void);
rtapi_realtime_type_t rtapi_get_realtime_type(void);
/* Display name of a realtime type, as printed by `rtapi_app check_rt`. */
const char *rtapi_realtime_type_name(int type);

/* ---- privileged helpers (plain calls: no setuid in OpenEMC) ---- */
int rtapi_open_as_root(const char *filename, int mode);
int rtapi_spawn_as_root(pid_t *pid, const char *path,
                        const posix_spawn_file_actions_t *file_actions,
                        const posix_spawnattr_t *attrp,
                        char *const argv[], char *const envp[]);
int rtapi_spawnp_as_root(pid_t *pid, const char *path,
                         const posix_spawn_file_actions_t *file_actions,
                         const posix_spawnattr_t *attrp,
                         char *const argv[], char *const envp[]);

/* ---- not available in uspace: always -ENOSYS ---- */
int rtapi_fifo_new(int key, int module_id, unsigned long int size, char mode);
int rtapi_fifo_delete(int fifo_id, int module_id);
int rtapi_irq_new(unsigned int irq_num, int owner, void (*handler)(void));
int rtapi_irq_delete(unsigned int irq_num);
int rtapi_enable_interrupt(unsigned int irq);
int rtapi_disable_interrupt(unsigned int irq);

/* ---- module parameters (rtapi.md §4) ---- */
/* Metadata of one module parameter; the symbol is rtapi_info_<name>. */
typedef struct {
    const char *name;        /* parameter (= variable) name */
    char type;               /* 'i' int, 'l' long, 's' char* */
    int count;               /* 0 = scalar, else array length */
    void *address;           /* the variable (or first array element) */
    const char *description;
} rtapi_param_info_t;

#define RTAPI_CAT2_(a, b) a##b
#define RTAPI_CAT_(a, b) RTAPI_CAT2_(a, b)
#ifdef __cplusplus
#define RTAPI_STATIC_ASSERT_(cond, msg) static_assert(cond, msg)
#define RTAPI_MP_LINKAGE_ extern "C"
#else
#define RTAPI_STATIC_ASSERT_(cond, msg) _Static_assert(cond, msg)
#define RTAPI_MP_LINKAGE_
#endif

#define RTAPI_MP_INFO_(var, letter, n, ctype, desc) \
    RTAPI_STATIC_ASSERT_((n) ? sizeof(var) >= (n) * sizeof(ctype) \
                             : sizeof(var) == sizeof(ctype), \
                         "module parameter " #var " has the wrong type or size"); \
    RTAPI_MP_LINKAGE_ RTAPI_VISIBLE const rtapi_param_info_t rtapi_info_##var = \
        { #var, letter, n, (void *)&(var), desc }

#define RTAPI_MP_INT(var, desc) RTAPI_MP_INFO_(var, 'i', 0, int, desc)
#define RTAPI_MP_LONG(var, desc) RTAPI_MP_INFO_(var, 'l', 0, long, desc)
#define RTAPI_MP_STRING(var, desc) RTAPI_MP_INFO_(var, 's', 0, char *, desc)
#define RTAPI_MP_ARRAY_INT(var, num, desc) RTAPI_MP_INFO_(var, 'i', num, int, desc)
#define RTAPI_MP_ARRAY_LONG(var, num, desc) RTAPI_MP_INFO_(var, 'l', num, long, desc)
#define RTAPI_MP_ARRAY_STRING(var, num, desc) RTAPI_MP_INFO_(var, 's', num, char *, desc)

/* Free-text module metadata, kept in section .rtapi_modinfo. */
#define RTAPI_MODINFO_(tag, text) \
    static const char RTAPI_CAT_(rtapi_modinfo_, __COUNTER__)[] \
        __attribute__((used, section(".rtapi_modinfo"))) = tag "=" text
#define MODULE_LICENSE(x) RTAPI_MODINFO_("license", x)
#define MODULE_AUTHOR(x) RTAPI_MODINFO_("author", x)
#define MODULE_DESCRIPTION(x) RTAPI_MODINFO_("description", x)
#define MODULE_INFO(tag, x) RTAPI_MODINFO_(#tag, x)
#define MODULE_PARM_DESC(var, desc) RTAPI_MODINFO_("parmdesc", #var ":" desc)

/* Make a module symbol global and record its name for the version script. */
#define EXPORT_SYMBOL(x) \
    static const char RTAPI_CAT_(rtapi_export_name_, __COUNTER__)[] \
        __attribute__((used, section(".rtapi_export"))) = #x; \
    extern __typeof__(x) x RTAPI_VISIBLE
#define EXPORT_SYMBOL_GPL(x) EXPORT_SYMBOL(x)

RTAPI_END_DECLS

#endif
