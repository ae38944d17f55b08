/* hal_thread.c: realtime threads: creation with period/priority rules, deletion, start/stop. */
#include <limits.h>
#include "hal_internal.h"
#include <stdio.h>

/* Base period for a new thread; the first thread fixes it via RTAPI. */
static long hal_thread_base_period(long period)
{
    long base;

    if (hal_data->base_period)
        return hal_data->base_period;
    base = rtapi_clock_set_period(0);
    if (base <= 0)
        base = rtapi_clock_set_period(period);
    if (hal_data->exact_base_period || base <= 0)
        base = period;
    hal_data->base_period = base;
    return base;
}

/* Apply the period rules (hal.md §8); returns the rounded period or <0. */
static long hal_thread_period(unsigned long period_nsec)
{
    long period = (long)period_nsec;
    long base = hal_thread_base_period(period);
    hal_thread_t *t;

    if (period < base) {
        HAL_LIB_ERR("new thread period %ld is less than clock period %ld\n", period, base);
        return -EINVAL;
    }
    period = ((period + base / 2) / base) * base;
    for (t = halpr_first_thread(); t; t = halpr_next_thread(t)) {
        if (period < t->period) {
            HAL_LIB_ERR("new thread period %ld is less than existing thread period %ld\n",
                        period, t->period);
            return -EINVAL;
        }
    }
    return period;
}

/* Create the pseudo comp __<name> with <name>.time/.tmax/.threadbeat. */
static int hal_thread_comp(hal_thread_t *t)
{
    char cname[HAL_NAME_LEN + 8];
    hal_s32_t **time_cell = hal_malloc(sizeof(void *));
    hal_s64_t **beat_cell = hal_malloc(sizeof(void *));
    hal_data_u *tmax = hal_malloc(sizeof(hal_data_u));
    int id, rc;

    snprintf(cname, sizeof(cname), "__%s", t->name);
    if (!time_cell || !beat_cell || !tmax)
        return -ENOMEM;
    id = hal_init(cname);
    if (id < 0)
        return id;
    rc = hal_pin_s32_newf(HAL_OUT, time_cell, id, "%s.time", t->name);
    if (rc == 0)
        rc = hal_param_s32_newf(HAL_RW, &tmax->s, id, "%s.tmax", t->name);
    if (rc == 0)
        rc = hal_pin_s64_newf(HAL_OUT, beat_cell, id, "%s.threadbeat", t->name);
    if (rc < 0) {
        hal_exit(id);
        return rc;
    }
    hal_ready(id);
    t->comp_ptr = SHMOFF(halpr_find_comp_by_id(id));
    ((hal_comp_t *)SHMPTR(t->comp_ptr))->is_thread_comp = 1;
    t->runtime = time_cell;
    t->maxtime = &tmax->s;
    t->threadbeat = beat_cell;
    return id;
}

/* Point a thread's time/tmax/threadbeat at its own scratch cells. */
static void hal_thread_scratch(hal_thread_t *t)
{
    t->scratch_s32_ptr = &t->scratch[0].s;
    t->scratch_s64_ptr = &t->scratch[2].ls;
    t->runtime = &t->scratch_s32_ptr;
    t->maxtime = &t->scratch[1].s;
    t->threadbeat = &t->scratch_s64_ptr;
}

/* Id of the RT comp now being set up (newest not-ready one): the thread's creator. */
static int hal_thread_creator(void)
{
    hal_comp_t *c;
    for (c = halpr_first_comp(); c; c = halpr_next_comp(c))
        if (c->type == HAL_COMP_RT && !c->ready && !c->is_thread_comp)
            return c->comp_id;
    return 0;
}

/* Allocate, name and list a new thread record; mutex held. */
static hal_thread_t *hal_thread_record(const char *name, long period, int uses_fp)
{
    hal_thread_t *t = halpr_obj_alloc(HAL_KIND_THREAD);

    if (!t)
        return NULL;
    strcpy(t->name, name);
    t->period = period;
    t->uses_fp = uses_fp;
    t->priority = hal_data->thread_count == 0 ? rtapi_prio_next_lower(rtapi_prio_highest())
                                              : rtapi_prio_next_lower(hal_data->last_thread_prio);
    hal_thread_scratch(t);
    t->creator_id = hal_thread_creator();
    return t;
}

/* Start the rtapi task of a fully set up thread. */
static int hal_thread_start_task(hal_thread_t *t, int owner_id)
{
    int task = rtapi_task_new(hal_thread_task, t, t->priority, owner_id, 0, t->uses_fp);

    if (task < 0) {
        HAL_LIB_ERR("could not create task for thread %s\n", t->name);
        return task;
    }
    t->task_id = task;
    if (rtapi_task_start(task, t->period) < 0) {
        HAL_LIB_ERR("could not start task for thread %s\n", t->name);
        rtapi_task_delete(task);
        return -EINVAL;
    }
    return 0;
}

/* Argument checks of hal_create_thread before the mutex. */
static int hal_thread_precheck(const char *name, unsigned long period_nsec)
{
    if (!hal_data || !hal_proc_is_rt) {
        HAL_ERR("create_thread called from a non-realtime process\n");
        return -EINVAL;
    }
    if (period_nsec == 0) {
        HAL_ERR("create_thread called with period of zero\n");
        return -EINVAL;
    }
    if (period_nsec < RTAPI_MIN_PERIOD_NS) {
        HAL_ERR("thread '%s': period %lu ns is shorter than %d ns; no machine runs a thread that often\n",
                name ? name : "", period_nsec, RTAPI_MIN_PERIOD_NS);
        return -EINVAL;
    }
    if (period_nsec > LONG_MAX / 4) {
        HAL_ERR("thread '%s': period %lu ns is too long\n", name ? name : "", period_nsec);
        return -EINVAL;
    }
    if (hal_data->lock & HAL_LOCK_CONFIG) {
        HAL_ERR("create_thread called while HAL is locked\n");
        return -EPERM;
    }
    return halpr_name_check("thread", name, HAL_NAME_LEN);
}

/* Create a periodic realtime thread (RT process only). */
int hal_create_thread(const char *name, unsigned long period_nsec, int uses_fp)
{
    hal_thread_t *t = NULL;
    long period;
    int rc = hal_thread_precheck(name, period_nsec);

    if (rc < 0)
        return rc;
    halpr_mutex_get();
    if (halpr_find_thread_by_name(name)) {
        HAL_ERR("duplicate thread name %s\n", name);
        rc = -EEXIST;
    }
    period = rc == 0 ? hal_thread_period(period_nsec) : rc;
    t = period > 0 ? hal_thread_record(name, period, uses_fp) : NULL;
    rc = period < 0 ? (int)period : (t ? hal_thread_comp(t) : -ENOMEM);
    if (rc > 0)
        rc = hal_thread_start_task(t, rc);
    if (rc < 0 && t) {
        if (t->comp_ptr)
            hal_exit(((hal_comp_t *)SHMPTR(t->comp_ptr))->comp_id);
        halpr_obj_free(HAL_KIND_THREAD, t);
    } else if (rc == 0) {
        hal_data->last_thread_prio = t->priority;
        hal_data->thread_count++;
        halpr_index_insert_head(&hal_data->threads, (hal_node_t *)t);
    }
    halpr_mutex_give();
    return rc;
}

/* A comp is going away: drop the pseudo comps of threads it created; mutex held. */
void halpr_thread_creator_exit(hal_comp_t *comp)
{
    hal_thread_t *t;
    for (t = halpr_first_thread(); t; t = halpr_next_thread(t)) {
        if (t->creator_id == comp->comp_id && t->comp_ptr) {
            t->creator_id = 0;
            hal_exit(((hal_comp_t *)SHMPTR(t->comp_ptr))->comp_id);
        }
    }
}

/* The pseudo comp of a thread is going away: park the thread's cells; mutex held. */
void halpr_thread_park(hal_comp_t *comp)
{
    hal_thread_t *t;
    for (t = halpr_first_thread(); t; t = halpr_next_thread(t)) {
        if (t->comp_ptr == SHMOFF(comp)) {
            hal_thread_scratch(t);
            t->comp_ptr = 0;
        }
    }
}

/* Stop all threads, end the task, free the thread and its entries; mutex held. */
int halpr_thread_delete(hal_thread_t *t)
{
    hal_data->threads_running = 0;
    rtapi_task_delete(t->task_id);
    halpr_entry_list_free(&t->funct_list);
    halpr_entry_list_free(&t->init_list);
    if (t->comp_ptr)
        hal_exit(((hal_comp_t *)SHMPTR(t->comp_ptr))->comp_id);
    halpr_index_remove(&hal_data->threads, (hal_node_t *)t);
    halpr_obj_free(HAL_KIND_THREAD, t);
    return 0;
}

/* Delete a thread by name (stops all threads). */
int hal_thread_delete(const char *name)
{
    hal_thread_t *t;
    int rc;

    if (!hal_data || !hal_proc_is_rt) {
        HAL_ERR("thread_delete called from a non-realtime process\n");
        return -EINVAL;
    }
    if (hal_data->lock & HAL_LOCK_CONFIG) {
        HAL_ERR("thread_delete called while HAL is locked\n");
        return -EPERM;
    }
    halpr_mutex_get();
    t = halpr_find_thread_by_name(name);
    if (!t) {
        HAL_ERR("thread '%s' not found\n", name);
        rc = -EINVAL;
    } else {
        rc = halpr_thread_delete(t);
    }
    halpr_mutex_give();
    return rc;
}

/* Set the global run flag of all threads. */
static int hal_threads_run(int run, const char *what)
{
    int rc = halpr_check_unlocked(what, HAL_LOCK_RUN, "%s called while HAL is locked");

    if (rc < 0)
        return rc;
    __atomic_store_n(&hal_data->threads_running, run, __ATOMIC_RELEASE);
    return 0;
}

/* start: let threads run their functs. */
int hal_start_threads(void)
{
    return hal_threads_run(1, "start_threads");
}

/* stop: threads keep ticking but run no functs. */
int hal_stop_threads(void)
{
    return hal_threads_run(0, "stop_threads");
}

/* setexact_for_test_suite_only: the next base period is used verbatim (halcmd prints the notes). */
int hal_set_exact_period(void)
{
    if (!hal_data) {
        HAL_ERR("set_exact called before init\n");
        return -EINVAL;
    }
    if (hal_data->threads.list_ptr || hal_data->base_period)
        return -EBUSY;
    hal_data->exact_base_period = 1;
    return 0;
}
