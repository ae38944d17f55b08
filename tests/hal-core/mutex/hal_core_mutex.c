/* hal_core_mutex.c: unit test of the cross-process HAL mutex: concurrent creators, recursion, dead-holder take-over. */
#include "hal.h"
#include "hal_priv.h"
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>

#define PER_CHILD 1500

/* Child body: its own component plus PER_CHILD signals created in interleaved order. */
static int child_work(int n)
{
    char name[32];
    int i, id;

    id = hal_init(n ? "child1" : "child0");
    if (id < 0)
        return 1;
    for (i = 0; i < PER_CHILD; i++) {
        snprintf(name, sizeof(name), "s.%05d.%d", i, n);
        if (hal_signal_new(name, HAL_BIT) < 0)
            return 1;
    }
    return hal_exit(id) < 0;
}

/* Count signals and check the list is in strcmp order. */
static void check_sigs(void)
{
    hal_sig_t *s, *prev = NULL;
    int n = 0, sorted = 1;

    halpr_mutex_get();
    for (s = halpr_first_sig(); s; prev = s, s = halpr_next_sig(s)) {
        n++;
        if (prev && strcmp(prev->name, s->name) >= 0)
            sorted = 0;
    }
    halpr_mutex_give();
    printf("signals %d sorted %d\n", n, sorted);
}

/* Fork two concurrent creators and wait for them. */
static void concurrent(void)
{
    pid_t pid[2];
    int i, status, ok = 1;

    for (i = 0; i < 2; i++) {
        pid[i] = fork();
        if (pid[i] == 0)
            _exit(child_work(i));
    }
    for (i = 0; i < 2; i++) {
        waitpid(pid[i], &status, 0);
        ok = ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    }
    printf("children ok %d\n", ok);
    check_sigs();
}

/* A child takes the mutex and dies holding it; the parent must still get it. */
static void dead_holder(void)
{
    pid_t pid = fork();
    int status;

    if (pid == 0) {
        halpr_mutex_get();
        halpr_mutex_get();
        _exit(0);
    }
    waitpid(pid, &status, 0);
    printf("holder died, owner set %d\n", hal_data->mutex.owner_tid != 0);
    halpr_mutex_get();
    printf("parent took the mutex, depth %d\n", hal_data->mutex.depth);
    halpr_mutex_give();
    printf("released %d\n", hal_data->mutex.owner_tid == 0);
}

/* Recursion: try-lock succeeds for the holder, depth counts levels. */
static void recursion(void)
{
    int got;

    halpr_mutex_get();
    got = halpr_mutex_try();
    printf("try while held by self %d, depth %d\n", got, hal_data->mutex.depth);
    halpr_mutex_give();
    halpr_mutex_give();
    printf("free after two gives %d\n", hal_data->mutex.owner_tid == 0);
}

/* Run the three sections with the parent's component mapped. */
int main(void)
{
    int id;

    setvbuf(stdout, NULL, _IONBF, 0);
    id = hal_init("parent");
    if (id < 0)
        return 1;
    concurrent();
    recursion();
    dead_holder();
    hal_exit(id);
    return 0;
}
