/* rtapi_internal.h: functions shared between librtapi's source files (not public). */
#ifndef RTAPI_INTERNAL_H
#define RTAPI_INTERNAL_H

#include <pthread.h>
#include <stdarg.h>

/* Non-zero when tasks use SCHED_FIFO (decided once per process). */
int rtapi_rt_enabled(void);
/* Print the scheduling mode note once per process (stderr). */
void rtapi_rt_announce(void);
/* Lock memory and pre-fault the heap when realtime; once per process. */
void rtapi_rt_harden(void);
/* CPU all realtime tasks are pinned to, or -1 for no pinning. */
int rtapi_rt_cpu(void);


#include "rtapi.h"

/* Start the realtime message queue and its 10 ms writer thread (once). */
void rtapi_msg_queue_start(void);
/* Queue a message from a realtime task; 0, or -1 when the queue is full. */
int rtapi_msg_queue(int level, const char *fmt, va_list ap);
/* Write out everything queued so far. */
void rtapi_msg_flush(void);

/* One task, allocated by rtapi_task_new; the table of pointers lives in rtapi_task.c. */
typedef struct {
    int id;                   /* index in rtapi_tasks */
    int started;              /* thread created */
    pthread_t thread;
    void (*code)(void *);
    void *arg;
    int prio;
    int owner;
    unsigned long stacksize;
    long long period_ns;
    long long next_deadline;  /* absolute CLOCK_MONOTONIC ns of the next wake-up */
    long long wake_time;      /* when the current cycle began */
    long pll_correction;      /* ns added to each period, +-1% */
    volatile int deleting;    /* set by rtapi_task_delete */
    volatile int paused;      /* set by rtapi_task_pause */
    rtapi_task_stats_t stats;
} rtapi_task_t;

extern rtapi_task_t *rtapi_tasks[RTAPI_MAX_TASKS];
/* Id of the calling task thread, -1 elsewhere. */
extern __thread int rtapi_self_task;
/* Body of a task thread: set up scheduling, run the task code. */
void *rtapi_task_thread(void *arg);
/* Block until a paused task is resumed or deleted (no locks held). */
void rtapi_task_wait_resume(rtapi_task_t *task);

/* Hold off every task (non-realtime mode; nests); no-op when realtime. */
void rtapi_tasks_lock(void);
/* Undo one rtapi_tasks_lock. */
void rtapi_tasks_unlock(void);
/* Drop every level this thread holds; returns the depth for rtapi_tasks_relock. */
int rtapi_tasks_release_all(void);
/* Re-take the non-realtime mutex to the depth returned by rtapi_tasks_release_all. */
void rtapi_tasks_relock(int depth);

#endif
