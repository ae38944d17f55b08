/* uprog.c: a hand-written userspace HAL program built with halcompile --compile --userspace. */
#include <stdio.h>
#include "hal.h"

/* Print a line so the test can run it without HAL running. */
int main(void)
{
    printf("uprog built, HAL_NAME_LEN=%d\n", HAL_NAME_LEN);
    return 0;
}
