/* mb2hal_log.c: LinuxCNC mb2hal's INIT_DEBUG log on stdout ("mb2hal FUNCTION LEVEL: text"). */
#include "mb2hal_log.h"

#include <stdarg.h>
#include <stdio.h>

/* Prints "mb2hal WHERE LEVEL: text" on stdout when debug >= level, flushed at once. */
void mb_log(int debug, mb_log_level_t level, const char *where, const char *fmt, ...)
{
    static const char *const names[] = {[MB_LOG_ERR] = "ERROR", [MB_LOG_OK] = "OK",
                                        [MB_LOG_DEBUG] = "DEBUG"};
    va_list ap;
    if (debug < (int)level)
        return;
    printf("mb2hal %s %s: ", where, names[level]);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
    fflush(stdout);
}
