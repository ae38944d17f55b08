component ucomp "A userspace component with count=/names= handling";
pin in s32 in "Input";
pin out s32 out "Twice the input";
option userspace yes;
option userinit yes;
license "GPL";
;;
#include <signal.h>
#include <unistd.h>
#include <stdio.h>

static volatile sig_atomic_t done;

/* Stop the main loop on SIGTERM/SIGINT. */
static void on_signal(int sig)
{
    (void)sig;
    done = 1;
}

/* Show the arguments left after count=/names= were removed, and names= as the names[] array. */
void userinit(int argc, char **argv)
{
    int i;
    printf("userinit argc=%d", argc);
    for (i = 1; i < argc; i++) printf(" argv[%d]=%s", i, argv[i]);
    printf(" last=%s", argv[argc] ? "set" : "NULL");
    for (i = 0; i < 16 && names[i]; i++) printf(" names[%d]=%s", i, names[i]);
    printf("\n");
    fflush(stdout);
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);
}

/* Copy in*2 to out until asked to stop. */
void user_mainloop(void)
{
    while (!done) {
        FOR_ALL_INSTS() out = in * 2;
        usleep(1000);
    }
}
