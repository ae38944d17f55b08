/* hal_mutex.c: the recursive cross-process HAL mutex kept in shared memory. */
#include "hal_internal.h"
#include <sched.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>
#include <sys/syscall.h>

/* Kernel thread id of the caller (unique system-wide, correct after fork). */
static int hal_mutex_tid(void)
{
    return (int)syscall(SYS_gettid);
}

/* Try once to take a free mutex for `me`; 1 on success. */
static int hal_mutex_grab(hal_mutex_t *m, int me)
{
    int expected = 0;
    if (!__atomic_compare_exchange_n(&m->owner_tid, &expected, me, 0,
                                     __ATOMIC_ACQUIRE, __ATOMIC_RELAXED))
        return 0;
    m->owner_pid = getpid();
    m->depth = 1;
    return 1;
}

/* Take over the mutex when its holder's process no longer exists; 1 if taken. */
static int hal_mutex_steal_from_dead(hal_mutex_t *m, int me)
{
    int holder = m->owner_tid;
    int pid = m->owner_pid;

    if (!holder || !pid || kill(pid, 0) == 0 || errno != ESRCH)
        return 0;
    if (!__atomic_compare_exchange_n(&m->owner_tid, &holder, me, 0,
                                     __ATOMIC_ACQUIRE, __ATOMIC_RELAXED))
        return 0;
    rtapi_print_msg(RTAPI_MSG_WARN, "HAL: mutex holder pid %d died; taking over\n", pid);
    m->owner_pid = getpid();
    m->depth = 1;
    return 1;
}

/* Take the recursive HAL mutex; spins briefly, then sleeps 100 us per try. */
void halpr_mutex_get(void)
{
    hal_mutex_t *m = &hal_data->mutex;
    struct timespec ts = {0, 100000};
    int me = hal_mutex_tid();
    long tries;

    if (m->owner_tid == me) {
        m->depth++;
        return;
    }
    for (tries = 0; !hal_mutex_grab(m, me); tries++) {
        if (tries < 50) {
            sched_yield();
            continue;
        }
        if (tries % 1000 == 0 && hal_mutex_steal_from_dead(m, me))
            return;
        nanosleep(&ts, NULL);
    }
}

/* Take the HAL mutex only if it is free or already ours; never waits. */
int halpr_mutex_try(void)
{
    hal_mutex_t *m = &hal_data->mutex;
    int me = hal_mutex_tid();

    if (m->owner_tid == me) {
        m->depth++;
        return 1;
    }
    return hal_mutex_grab(m, me);
}

/* Release one level of the HAL mutex held by the caller. */
void halpr_mutex_give(void)
{
    hal_mutex_t *m = &hal_data->mutex;

    if (m->owner_tid != hal_mutex_tid())
        return;
    if (--m->depth > 0)
        return;
    m->owner_pid = 0;
    __atomic_store_n(&m->owner_tid, 0, __ATOMIC_RELEASE);
}
