/* api_test.c: in-process checks of the rtapi.h API: messages, clock, ids, shm, tasks. */
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "rtapi.h"
#include "rtapi_bitops.h"
#include "rtapi_mutex.h"
#include "rtapi_string.h"

#define TEST_SHM_KEY 0x41504931

static volatile unsigned long long ticks;

/* Task body: count cycles. */
static void counter_task(void *arg)
{
    (void)arg;
    for (;;) {
        ticks++;
        rtapi_wait();
    }
}

/* Sleep ms milliseconds. */
static void sleep_ms(int ms)
{
    struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
    nanosleep(&ts, NULL);
}

/* Wait (bounded) until ticks exceeds value; returns 1 when it did. */
static int ticks_pass(unsigned long long value)
{
    for (int i = 0; i < 3000; i++) {
        if (ticks > value)
            return 1;
        sleep_ms(10);
    }
    return 0;
}

/* Message levels and the handler hook. */
static void check_messages(void)
{
    char buf[8];

    printf("default level %d\n", rtapi_get_msg_level());
    printf("set level 9 -> %d", rtapi_set_msg_level(9));
    printf(", level 0 -> %d\n", rtapi_set_msg_level(RTAPI_MSG_NONE));
    rtapi_print_msg(RTAPI_MSG_ERR, "must not appear\n");
    rtapi_set_msg_level(RTAPI_MSG_ALL);
    rtapi_print_msg(RTAPI_MSG_ALL, "level ALL goes to stdout\n");
    rtapi_set_msg_level(RTAPI_MSG_ERR);
    rtapi_print_msg(RTAPI_MSG_INFO, "must not appear either\n");
    rtapi_print("rtapi_print %d\n", 42);
    printf("snprintf -> %d [%s]\n", rtapi_snprintf(buf, sizeof buf, "%s", "truncated"), buf);
}

/* Timer period rules and delays. */
static void check_clock(void)
{
    long long t0 = rtapi_get_time();

    printf("period query %ld", rtapi_clock_set_period(0));
    printf(", set %ld", rtapi_clock_set_period(50000));
    printf(", query %ld", rtapi_clock_set_period(0));
    printf(", set again %ld\n", rtapi_clock_set_period(100000));
    rtapi_delay(1000);
    printf("time advances: %s, delay max %ld\n", rtapi_get_time() > t0 ? "yes" : "no",
           rtapi_delay_max());
}

/* Ids from the shared counter and reference-counted shm handles. */
static void check_ids_and_shm(void)
{
    int a = rtapi_init("a");
    int b = rtapi_init("b");
    int h1 = rtapi_shmem_new(TEST_SHM_KEY, a, 8192);
    int h2 = rtapi_shmem_new(TEST_SHM_KEY, b, 4096);
    char *p1, *p2;

    printf("ids consecutive: %s, exit unknown id -> %d\n", b == a + 1 ? "yes" : "no",
           rtapi_exit(9999));
    rtapi_shmem_getptr(h1, (void **)&p1);
    rtapi_shmem_getptr(h2, (void **)&p2);
    printf("same key same handle: %s, zero-filled: %s\n", h1 == h2 && p1 == p2 ? "yes" : "no",
           p1[0] == 0 && p1[8191] == 0 ? "yes" : "no");
    printf("bigger than existing -> %d", rtapi_shmem_new(TEST_SHM_KEY, a, 1 << 20));
    printf(", size 0 -> %d\n", rtapi_shmem_new(TEST_SHM_KEY + 1, a, 0));
    printf("delete x2 -> %d", rtapi_shmem_delete(h1, a));
    printf(" %d", rtapi_shmem_delete(h2, b));
    printf(", third -> %d", rtapi_shmem_delete(h1, a));
    printf(", getptr after -> %d\n", rtapi_shmem_getptr(h1, (void **)&p1));
    printf("exit ids -> %d", rtapi_exit(a));
    printf(" %d\n", rtapi_exit(b));
}

/* Task creation limits, pause/resume and delete. */
static void check_tasks(void)
{
    int bad = rtapi_task_new(counter_task, NULL, rtapi_prio_highest() + 1, 0, 0, 0);
    int id = rtapi_task_new(counter_task, NULL, rtapi_prio_lowest(), 0, 0, 0);
    unsigned long long frozen;

    printf("prio out of range -> %d, new -> %d", bad, id);
    printf(", start period 0 -> %d\n", rtapi_task_start(id, 0));
    printf("start -> %d", rtapi_task_start(id, 200000));
    printf(", again -> %d\n", rtapi_task_start(id, 200000));
    printf("runs: %s\n", ticks_pass(3) ? "yes" : "no");
    printf("pause -> %d\n", rtapi_task_pause(id));
    frozen = ticks;
    sleep_ms(100);
    /* at most the cycle already past its pause check completes */
    printf("paused task stands still: %s\n", ticks <= frozen + 1 ? "yes" : "no");
    frozen = ticks;
    printf("resume -> %d", rtapi_task_resume(id));
    printf(", runs again: %s\n", ticks_pass(frozen + 2) ? "yes" : "no");
    printf("self outside a task -> %d\n", rtapi_task_self());
    printf("delete -> %d", rtapi_task_delete(id));
    printf(", again -> %d", rtapi_task_delete(id));
    printf(", pause deleted -> %d\n", rtapi_task_pause(id));
}

/* Bit operations, the spin mutex and string helpers. */
static void check_helpers(void)
{
    unsigned long bits[2] = { 0, 0 };
    rtapi_mutex_t m = 0;
    char buf[6], **argv;
    int argc;

    rtapi_set_bit(65, bits);
    printf("bit 65: %d", rtapi_test_bit(65, bits));
    printf(", test_and_clear: %d", rtapi_test_and_clear_bit(65, bits));
    printf(" then %d\n", rtapi_test_bit(65, bits));
    printf("mutex try %d", rtapi_mutex_try(&m));
    printf(", try again %d", rtapi_mutex_try(&m));
    rtapi_mutex_give(&m);
    printf(", after give %d\n", rtapi_mutex_try(&m));
    size_t n = rtapi_strlcpy(buf, "abcdefgh", sizeof buf);

    printf("strlcpy -> %zu [%s]", n, buf);
    buf[2] = '\0';
    n = rtapi_strlcat(buf, "xyz", sizeof buf);
    printf(", strlcat -> %zu [%s]\n", n, buf);
    argv = rtapi_argv_split(0, "  one two\tthree ", &argc);
    printf("argv_split: %d [%s|%s|%s] %s\n", argc, argv[0], argv[1], argv[2],
           argv[3] ? "unterminated" : "terminated");
    rtapi_argv_free(argv);
    printf("fifo -> %d", rtapi_fifo_new(1, 1, 1, 'r'));
    printf(", irq -> %d, kernelspace %d\n", rtapi_irq_new(1, 1, NULL), rtapi_is_kernelspace());
}

/* Run every check group in order. */
int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    check_messages();
    check_clock();
    check_ids_and_shm();
    check_tasks();
    check_helpers();
    return 0;
}
