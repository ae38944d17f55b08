/* mot_report.c: operator messages from motmod and the homing module, queued for task (realtime safe). */
#include <stdarg.h>
#include "rtapi.h"
#include "mot_priv.h"

/* Format into a stack buffer and queue it; before the segment exists, print it instead. */
void mot_report(const char *fmt, ...)
{
    char text[EMCMOT_ERROR_LEN];
    va_list ap;

    va_start(ap, fmt);
    rtapi_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (mot && mot->shm) {
        emcmot_error_push(mot->shm, EMCMOT_MSG_ERROR, text);
        mot_command_reported(text);
    }
    else
        rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", text);
}
