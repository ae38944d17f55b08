/* hal_memory.c: the HAL shared-memory block: attach/create, bump allocator, object free lists. */
#include "hal_internal.h"
#include <stdlib.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>
#include <sys/ipc.h>
#include <sys/shm.h>

char *hal_shmem_base;
hal_data_t *hal_data;
int hal_proc_is_rt;
int hal_proc_lib_id;
int hal_proc_comps;

static int hal_shm_id = -1;

/* Byte size of one object of each kind (index = HAL_KIND_*). */
_Static_assert(sizeof(hal_funct_entry_t) == 32, "thread entries must fill half a cache line");

static const int hal_kind_size[HAL_KIND_COUNT] = {
    sizeof(hal_comp_t), sizeof(hal_pin_t), sizeof(hal_param_t), sizeof(hal_oldname_t),
    sizeof(hal_sig_t), sizeof(hal_funct_t), sizeof(hal_thread_t), sizeof(hal_funct_entry_t),
};

/* Arena size: $OPENEMC_HAL_SIZE bytes, else the 32 MiB default. */
static long hal_arena_size(void)
{
    const char *env = getenv("OPENEMC_HAL_SIZE");
    char *end;
    long size;

    if (!env || !*env)
        return HAL_DEFAULT_SIZE;
    size = strtol(env, &end, 0);
    if (*end || size < HAL_MIN_SIZE || size > 0x7fff0000L) {
        HAL_ERR("OPENEMC_HAL_SIZE '%s' is not a size in bytes between %ld and %ld; using %ld\n",
                env, HAL_MIN_SIZE, 0x7fff0000L, HAL_DEFAULT_SIZE);
        return HAL_DEFAULT_SIZE;
    }
    return size;
}

/* Bucket count for the name hashes: about one per 2 KiB of arena, power of two. */
static int hal_bucket_count(long size)
{
    int n = 256;
    while (n < 65536 && (long)n * 2048 < size)
        n *= 2;
    return n;
}

/* Fill in the header of a freshly created (zeroed) block; version last. */
static void hal_shm_init(long size)
{
    int nb = hal_bucket_count(size);

    hal_data->shmem_size = size;
    hal_data->shmem_used = (sizeof(hal_data_t) + 15) & ~15L;
    hal_data->creator_pid = getpid();
    halpr_index_setup(&hal_data->comps, 256);
    halpr_index_setup(&hal_data->pins, nb);
    halpr_index_setup(&hal_data->params, nb);
    halpr_index_setup(&hal_data->sigs, nb);
    halpr_index_setup(&hal_data->functs, nb / 4);
    halpr_index_setup(&hal_data->threads, 64);
    __atomic_store_n(&hal_data->version, HAL_DATA_VERSION, __ATOMIC_RELEASE);
}

/* Wait (up to 2 s) for the creator to publish the version word, then check it. */
static int hal_shm_check_version(void)
{
    struct timespec ts = {0, 1000000};
    int i;

    for (i = 0; i < 2000 && !__atomic_load_n(&hal_data->version, __ATOMIC_ACQUIRE); i++)
        nanosleep(&ts, NULL);
    if (hal_data->version != HAL_DATA_VERSION) {
        HAL_ERR("version code mismatch: HAL memory has %08x, library expects %08x\n",
                hal_data->version, HAL_DATA_VERSION);
        return -EPROTO;
    }
    return 0;
}

/* Map an id returned by shmget; -EFAULT when shmat fails. */
static int hal_shm_map(int id)
{
    void *p = shmat(id, NULL, 0);
    if (p == (void *)-1) {
        HAL_ERR("could not map HAL shared memory: %s\n", strerror(errno));
        return -EFAULT;
    }
    hal_shm_id = id;
    hal_shmem_base = p;
    hal_data = p;
    return 0;
}

/* Attach to this instance's HAL block, creating it when absent. */
int hal_shm_attach(void)
{
    int key = rtapi_instance_key(RTAPI_HAL_KEY);
    long size = hal_arena_size();
    int tries, id, rc;

    if (hal_data)
        return 0;
    if (rtapi_instance() < 0)
        return -EINVAL;
    for (tries = 0; tries < 100; tries++) {
        id = shmget(key, 0, 0600);
        if (id >= 0) {
            rc = hal_shm_map(id);
            if (rc == 0 && (rc = hal_shm_check_version()) < 0)
                hal_shm_detach();
            return rc;
        }
        id = shmget(key, size, IPC_CREAT | IPC_EXCL | 0600);
        if (id >= 0) {
            rc = hal_shm_map(id);
            if (rc == 0)
                hal_shm_init(size);
            return rc;
        }
        if (errno != EEXIST)
            break;
        sched_yield();
    }
    HAL_ERR("could not create HAL shared memory (%ld bytes): %s\n", size, strerror(errno));
    return -ENOMEM;
}

/* Unmap the block; the last process to leave removes the segment. */
void hal_shm_detach(void)
{
    struct shmid_ds ds;

    if (!hal_data)
        return;
    if (shmctl(hal_shm_id, IPC_STAT, &ds) == 0 && ds.shm_nattch <= 1)
        shmctl(hal_shm_id, IPC_RMID, NULL);
    shmdt(hal_shmem_base);
    hal_shmem_base = NULL;
    hal_data = NULL;
    hal_shm_id = -1;
}

/* Library attach: one RTAPI id named HAL_LIB plus the HAL memory mapping. */
int hal_lib_attach(void)
{
    int id, rc;

    id = rtapi_init("HAL_LIB");
    if (id < 0) {
        HAL_ERR("could not init RTAPI: %d\n", id);
        return id;
    }
    rc = hal_shm_attach();
    if (rc < 0) {
        rtapi_exit(id);
        return rc;
    }
    hal_proc_lib_id = id;
    return 0;
}

/* First attach of a user process: costs one id (library attach) like LinuxCNC. */
int hal_attach_user(void)
{
    if (hal_data)
        return 0;
    return hal_lib_attach();
}

/* Bump-allocate size bytes at a multiple of align (a power of two); NULL when full. */
static void *halpr_malloc_aligned(long size, long align)
{
    long start;

    start = (hal_data->shmem_used + align - 1) & ~(align - 1);
    if (size > hal_data->shmem_size - start)
        return NULL;
    hal_data->shmem_used = start + size;
    return SHMPTR(start);
}

/* Bump-allocate size bytes (8-aligned, 16 for >= 16 bytes); NULL when full. Mutex held. */
void *halpr_malloc(long size)
{
    if (size < 8)
        size = 8;
    return halpr_malloc_aligned(size, size >= 16 ? 16 : 8);
}

/* Allocate never-freed memory in HAL shared memory (spec/hal.md §12). */
void *hal_malloc(long int size)
{
    void *p;

    if (!hal_data) {
        HAL_ERR("hal_malloc called before init\n");
        return NULL;
    }
    if (size <= 0)
        size = 8;
    halpr_mutex_get();
    p = halpr_malloc(size);
    halpr_mutex_give();
    if (!p)
        HAL_ERR("insufficient memory for hal_malloc(%ld)\n", size);
    else
        memset(p, 0, size);
    return p;
}

/* Take a zeroed object of `kind` from its free list or the arena. Mutex held. */
void *halpr_obj_alloc(int kind)
{
    hal_kind_t *k = &hal_data->kinds[kind];
    int size = hal_kind_size[kind];
    void *obj;

    if (k->free_ptr) {
        obj = SHMPTR(k->free_ptr);
        k->free_ptr = *(int *)obj;
        k->recycled--;
    } else {
        /* thread entries sit on a boundary of their (power-of-two) size: one cache line */
        obj = kind == HAL_KIND_ENTRY ? halpr_malloc_aligned(size, size) : halpr_malloc(size);
        if (!obj) {
            HAL_ERR("insufficient memory for a new HAL object\n");
            return NULL;
        }
    }
    memset(obj, 0, size);
    k->active++;
    return obj;
}

/* Return an object to its kind's free list. Mutex held.  Thread entries are
 * never reused: a running thread may still be walking a just-removed one. */
void halpr_obj_free(int kind, void *obj)
{
    hal_kind_t *k = &hal_data->kinds[kind];

    if (kind == HAL_KIND_ENTRY) {
        k->active--;
        return;
    }
    memset(obj, 0, hal_kind_size[kind]);
    *(int *)obj = k->free_ptr;
    k->free_ptr = SHMOFF(obj);
    k->active--;
    k->recycled++;
}
