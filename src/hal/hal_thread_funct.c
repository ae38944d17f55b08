/* hal_thread_funct.c: addf / initf / delf: function slots in threads (position rules of hal.md §8). */
#include "hal_internal.h"
#include <time.h>

/* Number of entries in a list. */
static int hal_entry_count(int list)
{
    int n = 0;
    for (; list; list = ((hal_funct_entry_t *)SHMPTR(list))->next_ptr)
        n++;
    return n;
}

/* Link an entry after `index` existing entries, publishing it to the RT reader last. */
static void hal_entry_insert(int *list, int index, hal_funct_entry_t *e)
{
    int *link = list;
    while (index-- > 0)
        link = &((hal_funct_entry_t *)SHMPTR(*link))->next_ptr;
    e->next_ptr = *link;
    __atomic_store_n(link, SHMOFF(e), __ATOMIC_RELEASE);
}

/* Resolve a 1-based (+N / -N) position to an insertion index; <0 error. */
static int hal_entry_index(int list, int position)
{
    int n = hal_entry_count(list);
    int index = position > 0 ? position - 1 : n + position + 1;

    if (position > 0 && index > n) {
        HAL_ERR("position '%d' is too high\n", position);
        return -EINVAL;
    }
    if (position < 0 && index < 0) {
        HAL_ERR("position '%d' is too low\n", position);
        return -EINVAL;
    }
    return index;
}

/* Find funct and thread in the order the spec checks them; mutex held. */
static int hal_addf_lookup(const char *funct_name, const char *thread_name, int position,
                           hal_funct_t **fp, hal_thread_t **tp)
{
    if (position == 0) {
        HAL_ERR("bad position: 0\n");
        return -EINVAL;
    }
    *fp = halpr_find_funct_by_name(funct_name);
    if (!*fp) {
        HAL_ERR("function '%s' not found\n", funct_name);
        return -EINVAL;
    }
    if ((*fp)->users > 0 && !(*fp)->reentrant) {
        HAL_ERR("function '%s' may only be added to one thread\n", funct_name);
        return -EINVAL;
    }
    *tp = halpr_find_thread_by_name(thread_name);
    if (!*tp) {
        HAL_ERR("thread '%s' not found\n", thread_name);
        return -EINVAL;
    }
    return 0;
}

/* Common body of addf and initf. */
static int hal_addf_common(const char *funct_name, const char *thread_name, int position, int init)
{
    hal_funct_t *f;
    hal_thread_t *t;
    hal_funct_entry_t *e;
    int rc, index;

    rc = halpr_check_unlocked("add_funct", HAL_LOCK_CONFIG,
                              "add_funct_to_thread called while HAL is locked");
    if (rc < 0)
        return rc;
    halpr_mutex_get();
    rc = hal_addf_lookup(funct_name, thread_name, position, &f, &t);
    if (rc == 0 && init && t->init_done) {
        HAL_ERR("initf: thread '%s' init cycle already executed; '%s' was NOT registered\n",
                thread_name, funct_name);
        rc = -EALREADY;
    }
    index = rc == 0 ? hal_entry_index(init ? t->init_list : t->funct_list, position) : rc;
    e = index >= 0 ? halpr_obj_alloc(HAL_KIND_ENTRY) : NULL;
    if (e) {
        e->funct_ptr = SHMOFF(f);
        e->funct = f->funct;
        e->arg = f->arg;
        e->timing = f->timing;
        f->users++;
        hal_entry_insert(init ? &t->init_list : &t->funct_list, index, e);
    }
    halpr_mutex_give();
    return e ? 0 : (index < 0 ? index : -ENOMEM);
}

/* addf: schedule a funct in a thread at a position. */
int hal_add_funct_to_thread(const char *funct_name, const char *thread_name, int position)
{
    return hal_addf_common(funct_name, thread_name, position, 0);
}

/* initf: run a funct once in the thread's init cycle. */
int hal_init_funct_to_thread(const char *funct_name, const char *thread_name, int position)
{
    return hal_addf_common(funct_name, thread_name, position, 1);
}

/* Unlink the first entry of `funct` from a list; 1 if one was removed. */
static int hal_entry_remove(int *list, hal_funct_t *funct)
{
    int *link = list;
    while (*link) {
        hal_funct_entry_t *e = SHMPTR(*link);
        if (e->funct_ptr == SHMOFF(funct)) {
            __atomic_store_n(link, e->next_ptr, __ATOMIC_RELEASE);
            funct->users--;
            halpr_obj_free(HAL_KIND_ENTRY, e);
            return 1;
        }
        link = &e->next_ptr;
    }
    return 0;
}

/* Body of delf; mutex held. */
static int hal_delf_locked(const char *funct_name, const char *thread_name)
{
    hal_funct_t *f = halpr_find_funct_by_name(funct_name);
    hal_thread_t *t;

    if (!f) {
        HAL_ERR("function '%s' not found\n", funct_name);
        return -EINVAL;
    }
    if (f->users == 0) {
        HAL_ERR("function '%s' is not in use\n", funct_name);
        return -EINVAL;
    }
    t = halpr_find_thread_by_name(thread_name);
    if (!t) {
        HAL_ERR("thread '%s' not found\n", thread_name);
        return -EINVAL;
    }
    if (!hal_entry_remove(&t->funct_list, f) &&
        (t->init_done || !hal_entry_remove(&t->init_list, f))) {
        HAL_ERR("thread '%s' doesn't use %s\n", thread_name, funct_name);
        return -EINVAL;
    }
    return 0;
}

/* delf: remove a funct from a thread. */
int hal_del_funct_from_thread(const char *funct_name, const char *thread_name)
{
    int rc;

    rc = halpr_check_unlocked("del_funct", HAL_LOCK_CONFIG,
                              "del_funct_from_thread called while HAL is locked");
    if (rc < 0)
        return rc;
    if (!thread_name) {
        HAL_ERR("missing thread name\n");
        return -EINVAL;
    }
    halpr_mutex_get();
    rc = hal_delf_locked(funct_name, thread_name);
    halpr_mutex_give();
    return rc;
}

/* In rtapi_app, wait (max 2 s) until a thread busy running functs finishes that pass,
 * so a module's code is not unloaded while the thread may still be inside it. */
static void hal_thread_quiesce(hal_thread_t *t)
{
    struct timespec ts = {0, 100000};
    unsigned seq = __atomic_load_n(&t->cycle_seq, __ATOMIC_SEQ_CST);
    int i;

    if (!hal_proc_is_rt || rtapi_task_self() >= 0)
        return;
    for (i = 0; i < 20000 && __atomic_load_n(&t->in_cycle, __ATOMIC_SEQ_CST) &&
                __atomic_load_n(&t->cycle_seq, __ATOMIC_SEQ_CST) == seq; i++)
        nanosleep(&ts, NULL);
}

/* Remove every use of a funct from every thread (cyclic and init); mutex held. */
void halpr_thread_drop_funct(hal_funct_t *funct)
{
    hal_thread_t *t;
    int removed;

    for (t = halpr_first_thread(); t && funct->users > 0; t = halpr_next_thread(t)) {
        removed = 0;
        while (hal_entry_remove(&t->funct_list, funct))
            removed = 1;
        while (hal_entry_remove(&t->init_list, funct))
            removed = 1;
        if (removed)
            hal_thread_quiesce(t);
    }
}

/* Free a whole entry list, releasing the functs' users; mutex held. */
void halpr_entry_list_free(int *list)
{
    while (*list) {
        hal_funct_entry_t *e = SHMPTR(*list);
        __atomic_store_n(list, e->next_ptr, __ATOMIC_RELEASE);
        halpr_entry_funct(e)->users--;
        halpr_obj_free(HAL_KIND_ENTRY, e);
    }
}
