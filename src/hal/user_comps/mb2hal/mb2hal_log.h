/* mb2hal_log.h: LinuxCNC mb2hal's INIT_DEBUG log on stdout ("mb2hal FUNCTION LEVEL: text"). */
#ifndef MB2HAL_LOG_H
#define MB2HAL_LOG_H

/* Message levels, compared with INIT_DEBUG (or a transaction's DEBUG). */
typedef enum { MB_LOG_ERR = 1, MB_LOG_OK = 2, MB_LOG_DEBUG = 3 } mb_log_level_t;

/* LinuxCNC's link type numbers, as its log shows them. */
enum { MB_LOG_LINK_RTU = 0, MB_LOG_LINK_TCP = 1 };

/* Prints "mb2hal WHERE LEVEL: text" on stdout when debug >= level. */
void mb_log(int debug, mb_log_level_t level, const char *where, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
