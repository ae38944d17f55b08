/* rtapi_wait.c: task thread body, periodic wait with catch-up, PLL and the non-RT mutex. */
#define _GNU_SOURCE
#include <alloca.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "rtapi.h"
#include "rtapi_internal.h"

#define STACK_PREFAULT_BYTES (256 * 1024)

__thread int rtapi_self_task = -1;
static __thread rtapi_task_t *self_task;   /* the calling task's record (no table lookup in the cycle) */
/* Non-realtime mode: held by a task except while it sleeps, so tasks never overlap. */
static pthread_mutex_t nonrt_lock = PTHREAD_MUTEX_INITIALIZER;
static __thread int nonrt_depth;
/* Non-task threads (the master serving a command, shutdown) waiting for the mutex: a task that
   overruns lets them in instead of keeping the mutex through back-to-back catch-up cycles. */
static atomic_int command_waiters;

/* Take the non-realtime mutex (nesting per thread); no-op when realtime. */
void rtapi_tasks_lock(void)
{
    if (rtapi_rt_enabled())
        return;
    if (nonrt_depth++ != 0)
        return;
    if (rtapi_self_task >= 0) {
        pthread_mutex_lock(&nonrt_lock);
        return;
    }
    atomic_fetch_add(&command_waiters, 1);
    pthread_mutex_lock(&nonrt_lock);
    atomic_fetch_sub(&command_waiters, 1);
}

/* An overrunning task never sleeps, so it hands the mutex to waiting commands here and
   waits until they have taken it (without this, stop and unload could never get in). */
static void yield_to_commands(void)
{
    int depth;

    if (atomic_load(&command_waiters) == 0)
        return;
    depth = rtapi_tasks_release_all();
    while (atomic_load(&command_waiters) > 0)
        sched_yield();
    rtapi_tasks_relock(depth);
}

/* Release one level of the non-realtime mutex. */
void rtapi_tasks_unlock(void)
{
    if (nonrt_depth == 0)
        return;
    if (--nonrt_depth == 0)
        pthread_mutex_unlock(&nonrt_lock);
}

/* Release the mutex completely; returns the depth to restore. */
int rtapi_tasks_release_all(void)
{
    int depth = nonrt_depth;

    if (depth > 0) {
        nonrt_depth = 0;
        pthread_mutex_unlock(&nonrt_lock);
    }
    return depth;
}

/* Re-take the mutex at the given depth. */
void rtapi_tasks_relock(int depth)
{
    if (depth > 0) {
        pthread_mutex_lock(&nonrt_lock);
        nonrt_depth = depth;
    }
}

/* Touch the top of the stack so page faults do not happen in the cycle. */
static void prefault_stack(void)
{
    volatile char *p = alloca(STACK_PREFAULT_BYTES);

    for (int i = 0; i < STACK_PREFAULT_BYTES; i += 4096)
        p[i] = 0;
}

/* Thread body: cancellation only inside the period sleep; run the task code. */
void *rtapi_task_thread(void *arg)
{
    rtapi_task_t *task = arg;
    char name[16];

    pthread_setcancelstate(PTHREAD_CANCEL_DISABLE, NULL);
    rtapi_self_task = task->id;
    self_task = task;
    snprintf(name, sizeof name, "rtapi_app:T#%d", rtapi_self_task);
    pthread_setname_np(pthread_self(), name);
    if (rtapi_rt_enabled())
        prefault_stack();
    rtapi_tasks_lock();
    if (!task->deleting) {
        task->wake_time = rtapi_get_time();
        task->code(task->arg);
    }
    rtapi_tasks_release_all();
    return NULL;
}

/* Print the once-per-session realtime delay warning (SCHED_FIFO only). */
static void report_overrun(rtapi_task_t *task)
{
    static int reported;

    if (!rtapi_rt_enabled() || reported)
        return;
    reported = 1;
    rtapi_print_msg(RTAPI_MSG_ERR, "Unexpected realtime delay on task %d with period %lld\n"
                    "This Message will only display once per session.\n"
                    "Run the Latency Test and resolve before continuing.\n",
                    task->id, task->period_ns);
}

/* Sleep until the absolute deadline with the mutex released; cancellable only here. */
static void sleep_until(long long deadline)
{
    struct timespec ts = { deadline / 1000000000LL, deadline % 1000000000LL };
    int depth = rtapi_tasks_release_all();

    pthread_setcancelstate(PTHREAD_CANCEL_ENABLE, NULL);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
        ;
    pthread_setcancelstate(PTHREAD_CANCEL_DISABLE, NULL);
    rtapi_tasks_relock(depth);
}

/* Leave the thread when the task is being deleted. */
static void exit_if_deleting(rtapi_task_t *task)
{
    if (!task->deleting)
        return;
    rtapi_tasks_release_all();
    pthread_exit(NULL);
}

/* Record the execution time of the cycle that just ended. */
static void account_cycle(rtapi_task_t *task, long long now)
{
    long long exec = now - task->wake_time;

    task->stats.cycles++;
    task->stats.last_exec_ns = exec;
    if (exec > task->stats.max_exec_ns)
        task->stats.max_exec_ns = exec;
}

/* Hold a paused task, with no lock held; resume restarts the period. */
static void handle_pause(rtapi_task_t *task)
{
    int depth;

    if (!task->paused)
        return;
    depth = rtapi_tasks_release_all();
    rtapi_task_wait_resume(task);
    rtapi_tasks_relock(depth);
    task->next_deadline = rtapi_get_time();
}

/* Sleep to the next period start; a deadline already past is an overrun and the
   cycle runs at once (missed periods are caught up back-to-back, none skipped). */
void rtapi_wait(void)
{
    rtapi_task_t *task;
    long long now, deadline, late;

    task = self_task;
    if (!task)
        return;
    now = rtapi_get_time();
    account_cycle(task, now);
    exit_if_deleting(task);
    deadline = task->next_deadline;
    if (now >= deadline) {
        task->stats.overruns++;
        report_overrun(task);
        yield_to_commands();
    } else {
        sleep_until(deadline);
    }
    handle_pause(task);
    exit_if_deleting(task);
    now = rtapi_get_time();
    deadline = task->next_deadline;
    late = now > deadline ? now - deadline : 0;
    task->stats.last_wake_ns = late;
    if (late > task->stats.max_wake_ns)
        task->stats.max_wake_ns = late;
    task->wake_time = now;
    task->next_deadline = deadline + task->period_ns + task->pll_correction;
}

/* Absolute time the calling task wakes next. */
long long rtapi_task_pll_get_reference(void)
{
    return self_task ? self_task->next_deadline : 0;
}

/* Set the per-period correction, clamped to +-1% of the period. */
int rtapi_task_pll_set_correction(long value)
{
    rtapi_task_t *task;
    long limit;

    task = self_task;
    if (!task)
        return -EINVAL;
    limit = (long)(task->period_ns / 100);
    if (value > limit)
        value = limit;
    if (value < -limit)
        value = -limit;
    task->pll_correction = value;
    return 0;
}

/* Restart the calling task's period from now. */
int rtapi_task_self_resync(void)
{
    rtapi_task_t *task;

    task = self_task;
    if (!task)
        return -EINVAL;
    task->next_deadline = rtapi_get_time() + task->period_ns;
    return 0;
}
