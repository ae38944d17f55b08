/* rtapi_msg.c: rtapi_print, message levels and the replaceable output handler. */
#include <stdio.h>
#include <stdarg.h>
#include "rtapi.h"
#include "rtapi_internal.h"

static int msg_level = RTAPI_MSG_ERR;
static rtapi_msg_handler_t msg_handler;

/* Default sink: stdout for RTAPI_MSG_ALL, stderr otherwise; flushed at once so
   output interleaves correctly with other processes sharing the file. */
static void default_handler(msg_level_t level, const char *fmt, va_list ap)
{
    FILE *out = level == RTAPI_MSG_ALL ? stdout : stderr;

    vfprintf(out, fmt, ap);
    fflush(out);
}

/* Send one message to the current handler; SCHED_FIFO tasks using the default
   sink queue it instead, so they never block in I/O. */
static void emit(msg_level_t level, const char *fmt, va_list ap)
{
    rtapi_msg_handler_t handler = msg_handler ? msg_handler : default_handler;

    if (!msg_handler && rtapi_self_task >= 0 && rtapi_rt_enabled()) {
        rtapi_msg_queue(level, fmt, ap);
        return;
    }
    handler(level, fmt, ap);
}

/* Always printed, on stdout. */
void rtapi_print(const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    emit(RTAPI_MSG_ALL, fmt, ap);
    va_end(ap);
}

/* Printed when level <= the current level and the current level is not NONE. */
void rtapi_print_msg(msg_level_t level, const char *fmt, ...)
{
    va_list ap;

    if (msg_level == RTAPI_MSG_NONE || (int)level > msg_level)
        return;
    va_start(ap, fmt);
    emit(level, fmt, ap);
    va_end(ap);
}

/* Set this process's message level (0..5). */
int rtapi_set_msg_level(int level)
{
    if (level < RTAPI_MSG_NONE || level > RTAPI_MSG_ALL)
        return -EINVAL;
    msg_level = level;
    return 0;
}

/* Current message level of this process. */
int rtapi_get_msg_level(void)
{
    return msg_level;
}

/* Replace the output sink (NULL = default). */
void rtapi_set_msg_handler(rtapi_msg_handler_t handler)
{
    msg_handler = handler;
}

/* The installed sink (the default one when none was set). */
rtapi_msg_handler_t rtapi_get_msg_handler(void)
{
    return msg_handler ? msg_handler : default_handler;
}

/* snprintf with the RTAPI name. */
int rtapi_snprintf(char *buf, unsigned long size, const char *fmt, ...)
{
    va_list ap;
    int len;

    va_start(ap, fmt);
    len = vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return len;
}

/* vsnprintf with the RTAPI name. */
int rtapi_vsnprintf(char *buf, unsigned long size, const char *fmt, va_list ap)
{
    return vsnprintf(buf, size, fmt, ap);
}
