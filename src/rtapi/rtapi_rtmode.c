/* rtapi_rtmode.c: choose realtime (SCHED_FIFO) or deterministic non-realtime mode. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <malloc.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/utsname.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_internal.h"

#define PREFAULT_BYTES (32 * 1024 * 1024)

static pthread_once_t decide_once = PTHREAD_ONCE_INIT;
static int rt_enabled;
static rtapi_realtime_type_t rt_type = RTAPI_REALTIME_UNINITIALIZED;

/* Non-zero when the kernel says it is PREEMPT_RT. */
static int kernel_is_preempt_rt(void)
{
    char c = 0;
    int fd = open("/sys/kernel/realtime", O_RDONLY);

    if (fd < 0)
        return 0;
    if (read(fd, &c, 1) != 1)
        c = 0;
    close(fd);
    return c == '1';
}

/* Non-zero when this process may use SCHED_FIFO (tried and undone). */
static int fifo_permitted(void)
{
    struct sched_param sp = { .sched_priority = 1 };
    struct sched_param normal = { .sched_priority = 0 };

    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
        return 0;
    sched_setscheduler(0, SCHED_OTHER, &normal);
    return 1;
}

/* Name the flavour of a realtime-capable kernel. */
static rtapi_realtime_type_t fifo_flavour(void)
{
    struct utsname un;

    if (kernel_is_preempt_rt())
        return RTAPI_REALTIME_PREEMPT_RT;
    if (uname(&un) == 0 && strstr(un.version, "PREEMPT_DYNAMIC"))
        return RTAPI_REALTIME_PREEMPT_DYNAMIC;
    return RTAPI_REALTIME_UNKNOWN_FIFO;
}

/* Decide the mode. SCHED_FIFO is used only on a PREEMPT_RT kernel where it is
   permitted, or when LINUXCNC_FORCE_REALTIME=1. Everything else -- including
   root on a plain kernel, as in CI -- runs the deterministic non-realtime mode
   (one process-wide mutex, missed periods caught up), so simulations and tests
   give the same results every time. */
static void decide(void)
{
    const char *force = getenv("LINUXCNC_FORCE_REALTIME");

    if (force && strcmp(force, "1") == 0)
        rt_enabled = 1;
    else
        rt_enabled = kernel_is_preempt_rt() && fifo_permitted();
    rt_type = rt_enabled ? fifo_flavour() : RTAPI_REALTIME_NONE;
}

/* Non-zero when tasks use SCHED_FIFO. */
int rtapi_rt_enabled(void)
{
    pthread_once(&decide_once, decide);
    return rt_enabled;
}

/* The realtime type, as check_rt reports it. */
rtapi_realtime_type_t rtapi_get_realtime_type(void)
{
    pthread_once(&decide_once, decide);
    return rt_type;
}

/* Non-zero when running realtime. */
int rtapi_is_realtime(void)
{
    return rtapi_rt_enabled();
}

/* uspace is never kernel space. */
int rtapi_is_kernelspace(void)
{
    return 0;
}

/* Display names of rtapi_realtime_type_t, index = type + 1. */
const char *rtapi_realtime_type_name(int type)
{
    static const char *const names[] = {
        "Uninitialized", "No realtime", "Unknown (SCHED_FIFO)", "Preempt Dynamic",
        "Preempt RT", "RTAI", "LXRT", "Xenomai", "Xenomai EVL"
    };

    if (type < -1 || type > RTAPI_REALTIME_XENOMAI_EVL)
        return "Unknown";
    return names[type + 1];
}

/* Print the mode note once. */
static void announce(void)
{
    if (rtapi_rt_enabled()) {
        fprintf(stderr, "Note: Using POSIX realtime\n");
        return;
    }
    if (!kernel_is_preempt_rt())
        fprintf(stderr, "Note: kernel is not PREEMPT_RT; running deterministic non-realtime "
                "threads (set LINUXCNC_FORCE_REALTIME=1 to force SCHED_FIFO).\n");
    fprintf(stderr, "Note: Using POSIX non-realtime\n");
}

/* Announce the mode once per process. */
void rtapi_rt_announce(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;

    pthread_once(&once, announce);
}

/* Raise limits, lock memory, pre-fault heap, ask for low DMA latency. */
static void harden(void)
{
    struct rlimit unlimited = { RLIM_INFINITY, RLIM_INFINITY };
    static int dma_fd = -1;
    int zero = 0;
    char *heap;

    setrlimit(RLIMIT_MEMLOCK, &unlimited);
    setrlimit(RLIMIT_RTPRIO, &(struct rlimit){ 99, 99 });
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
        perror("rtapi: mlockall");
    mallopt(M_TRIM_THRESHOLD, -1);
    mallopt(M_MMAP_MAX, 0);
    heap = malloc(PREFAULT_BYTES);
    if (heap) {
        for (long i = 0; i < PREFAULT_BYTES; i += 4096)
            ((volatile char *)heap)[i] = 0;
        free(heap);
    }
    dma_fd = open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
    if (dma_fd >= 0 && write(dma_fd, &zero, sizeof zero) != sizeof zero) {
        close(dma_fd);
        dma_fd = -1;
    }
}

/* Harden the process once, only when realtime. */
void rtapi_rt_harden(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;

    if (rtapi_rt_enabled())
        pthread_once(&once, harden);
}

/* Highest CPU listed in /sys/devices/system/cpu/isolated, or -1. */
static int highest_isolated_cpu(void)
{
    char buf[256], *p;
    int best = -1;
    FILE *f = fopen("/sys/devices/system/cpu/isolated", "r");

    if (!f)
        return -1;
    if (fgets(buf, sizeof buf, f)) {
        for (p = buf; *p;) {
            char *end;
            long v = strtol(p, &end, 10);
            if (end == p)
                break;
            if (v > best)
                best = (int)v;
            if (*end != ',' && *end != '-')
                break;
            p = end + 1;
        }
    }
    fclose(f);
    return best;
}

/* $RTAPI_CPU_NUMBER, else the highest isolated CPU, else -1 (with a note). */
int rtapi_rt_cpu(void)
{
    const char *env = getenv("RTAPI_CPU_NUMBER");
    int cpu;

    if (env && *env)
        return atoi(env);
    cpu = highest_isolated_cpu();
    if (cpu < 0)
        fprintf(stderr, "No isolated CPU's found, expect some latency or set "
                "RTAPI_CPU_NUMBER to select CPU\n");
    return cpu;
}

/* Highest priority usable by tasks (0 in non-realtime mode). */
int rtapi_prio_highest(void)
{
    return rtapi_rt_enabled() ? sched_get_priority_max(SCHED_FIFO) - 1 : 0;
}

/* Lowest priority usable by tasks (0 in non-realtime mode). */
int rtapi_prio_lowest(void)
{
    return rtapi_rt_enabled() ? sched_get_priority_min(SCHED_FIFO) : 0;
}

/* One step up, clamped to the highest. */
int rtapi_prio_next_higher(int prio)
{
    if (prio >= rtapi_prio_highest())
        return rtapi_prio_highest();
    if (prio < rtapi_prio_lowest())
        return rtapi_prio_lowest();
    return prio + 1;
}

/* One step down, clamped to the lowest. */
int rtapi_prio_next_lower(int prio)
{
    if (prio <= rtapi_prio_lowest())
        return rtapi_prio_lowest();
    if (prio > rtapi_prio_highest())
        return rtapi_prio_highest();
    return prio - 1;
}
