/* rtapi_task.c: task table: create, start, pause, resume, delete and statistics. */
#define _GNU_SOURCE
#include <limits.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_internal.h"

#define MIN_STACK_BYTES (1024 * 1024)

rtapi_task_t *rtapi_tasks[RTAPI_MAX_TASKS];
static pthread_mutex_t table_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_mutex_t pause_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t pause_cond = PTHREAD_COND_INITIALIZER;

/* The task for id, or NULL when id is out of range or unused. */
static rtapi_task_t *task_get(int task_id)
{
    if (task_id < 0 || task_id >= RTAPI_MAX_TASKS)
        return NULL;
    return rtapi_tasks[task_id];
}

/* Allocate a task and a table slot; the thread starts with rtapi_task_start. */
int rtapi_task_new(void (*taskcode)(void *), void *arg, int prio, int owner,
                   unsigned long int stacksize, int uses_fp)
{
    rtapi_task_t *task;
    int id;

    (void)uses_fp;
    if (!taskcode)
        return -EINVAL;
    if (prio < rtapi_prio_lowest() || prio > rtapi_prio_highest()) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi:task_new prio is not in bound lowest %i "
                        "highest %i priority %i\n", rtapi_prio_lowest(),
                        rtapi_prio_highest(), prio);
        return -EINVAL;
    }
    task = calloc(1, sizeof *task);
    if (!task)
        return -ENOMEM;
    task->code = taskcode;
    task->arg = arg;
    task->prio = prio;
    task->owner = owner;
    task->stacksize = stacksize;
    pthread_mutex_lock(&table_lock);
    for (id = 0; id < RTAPI_MAX_TASKS && rtapi_tasks[id]; id++)
        ;
    if (id < RTAPI_MAX_TASKS) {
        task->id = id;
        rtapi_tasks[id] = task;
    }
    pthread_mutex_unlock(&table_lock);
    if (id == RTAPI_MAX_TASKS) {
        free(task);
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: task_new: all %d task slots in use\n",
                        RTAPI_MAX_TASKS);
        return -ENOMEM;
    }
    return id;
}

static pthread_once_t cpu_once = PTHREAD_ONCE_INIT;
static int pinned_cpu = -1;

/* Look up the CPU for realtime tasks. */
static void pick_cpu(void)
{
    pinned_cpu = rtapi_rt_cpu();
}

/* The CPU realtime tasks are pinned to (looked up once). */
static int task_cpu(void)
{
    pthread_once(&cpu_once, pick_cpu);
    return pinned_cpu;
}

/* Fill attr: stack >= 1 MiB, SCHED_FIFO + CPU pinning when realtime. */
static void task_attr(pthread_attr_t *attr, rtapi_task_t *task)
{
    struct sched_param sp = { .sched_priority = task->prio };
    size_t stack = task->stacksize < MIN_STACK_BYTES ? MIN_STACK_BYTES : task->stacksize;

    pthread_attr_init(attr);
    pthread_attr_setstacksize(attr, stack);
    if (!rtapi_rt_enabled())
        return;
    pthread_attr_setinheritsched(attr, PTHREAD_EXPLICIT_SCHED);
    pthread_attr_setschedpolicy(attr, SCHED_FIFO);
    pthread_attr_setschedparam(attr, &sp);
    if (task_cpu() >= 0) {
        cpu_set_t set;
        CPU_ZERO(&set);
        CPU_SET(task_cpu(), &set);
        pthread_attr_setaffinity_np(attr, sizeof set, &set);
    }
}

/* Create the task's thread; its first cycle runs at once, then every period. */
int rtapi_task_start(int task_id, unsigned long int period_nsec)
{
    rtapi_task_t *task = task_get(task_id);
    pthread_attr_t attr;
    int rc;

    if (period_nsec < RTAPI_MIN_PERIOD_NS || period_nsec > LLONG_MAX / 4) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: task %d: period %lu ns is outside %d ns .. %lld ns\n",
                        task_id, period_nsec, RTAPI_MIN_PERIOD_NS, LLONG_MAX / 4);
        return -EINVAL;
    }
    if (!task || task->started)
        return -EINVAL;
    rtapi_rt_announce();
    rtapi_rt_harden();
    if (rtapi_rt_enabled())
        rtapi_msg_queue_start();
    task->period_ns = (long long)period_nsec;
    task->stats.period_ns = task->period_ns;
    task->wake_time = rtapi_get_time();
    task->next_deadline = task->wake_time + task->period_ns;
    task_attr(&attr, task);
    rc = pthread_create(&task->thread, &attr, rtapi_task_thread, task);
    if (rc == EPERM && rtapi_rt_enabled()) {
        fprintf(stderr, "rtapi: SCHED_FIFO refused for task %d; using normal scheduling\n",
                task_id);
        pthread_attr_setinheritsched(&attr, PTHREAD_INHERIT_SCHED);
        rc = pthread_create(&task->thread, &attr, rtapi_task_thread, task);
    }
    pthread_attr_destroy(&attr);
    if (rc != 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: task_start: pthread_create: %s\n",
                        strerror(rc));
        return -rc;
    }
    task->started = 1;
    return 0;
}

/* Stop a task at its next wait (cancelling its sleep), join it, free the slot. */
int rtapi_task_delete(int task_id)
{
    rtapi_task_t *task = task_get(task_id);
    int depth;

    if (!task || task_id == rtapi_self_task)
        return -EINVAL;
    if (task->started) {
        task->deleting = 1;
        pthread_mutex_lock(&pause_lock);
        pthread_cond_broadcast(&pause_cond);
        pthread_mutex_unlock(&pause_lock);
        pthread_cancel(task->thread);
        depth = rtapi_tasks_release_all();
        pthread_join(task->thread, NULL);
        rtapi_tasks_relock(depth);
    }
    pthread_mutex_lock(&table_lock);
    rtapi_tasks[task_id] = NULL;
    pthread_mutex_unlock(&table_lock);
    free(task);
    return 0;
}

/* Hold the task at its next rtapi_wait(). */
int rtapi_task_pause(int task_id)
{
    rtapi_task_t *task = task_get(task_id);

    if (!task)
        return -EINVAL;
    task->paused = 1;
    return 0;
}

/* Let a paused task run again; its period restarts from the resume time. */
int rtapi_task_resume(int task_id)
{
    rtapi_task_t *task = task_get(task_id);

    if (!task)
        return -EINVAL;
    pthread_mutex_lock(&pause_lock);
    task->paused = 0;
    pthread_cond_broadcast(&pause_cond);
    pthread_mutex_unlock(&pause_lock);
    return 0;
}

/* Block (no RTAPI locks held) while task is paused and not being deleted. */
void rtapi_task_wait_resume(rtapi_task_t *task)
{
    pthread_mutex_lock(&pause_lock);
    while (task->paused && !task->deleting)
        pthread_cond_wait(&pause_cond, &pause_lock);
    pthread_mutex_unlock(&pause_lock);
}

/* Id of the calling task. */
int rtapi_task_self(void)
{
    return rtapi_self_task >= 0 ? rtapi_self_task : -EINVAL;
}

/* Copy a task's statistics. */
int rtapi_task_get_stats(int task_id, rtapi_task_stats_t *stats)
{
    rtapi_task_t *task = task_get(task_id);

    if (!task || !stats)
        return -EINVAL;
    *stats = task->stats;
    return 0;
}

/* Reset a task's maxima. */
int rtapi_task_reset_stats(int task_id)
{
    rtapi_task_t *task = task_get(task_id);

    if (!task)
        return -EINVAL;
    task->stats.max_exec_ns = 0;
    task->stats.max_wake_ns = 0;
    return 0;
}
