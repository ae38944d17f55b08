/* usercomp.c: minimal user-space HAL component used by the loadusr -W/waitusr/unloadusr tests. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include "hal.h"

static volatile sig_atomic_t done;

/* SIGTERM/SIGINT handler: leave the main loop. */
static void on_signal(int sig)
{
    (void)sig;
    done = 1;
}

/* usercomp NAME: create component NAME with pin NAME.out, ready it, exit on SIGTERM. */
int main(int argc, char *argv[])
{
    const char *name = argc > 1 ? argv[1] : "usercomp";
    hal_bit_t **out;
    int comp = hal_init(name);
    if (comp < 0)
        return 1;
    out = hal_malloc(sizeof *out);
    if (!out || hal_pin_bit_newf(HAL_OUT, out, comp, "%s.out", name) < 0) {
        hal_exit(comp);
        return 1;
    }
    **out = 1;
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
    hal_ready(comp);
    while (!done)
        pause();
    hal_exit(comp);
    return 0;
}
