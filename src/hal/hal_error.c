/* hal_error.c: hal_strerror texts and the realtime-type query. */
#include "hal_internal.h"

/* Text for a negative HAL error code (spec/hal.md §14). */
const char *hal_strerror(int errnum)
{
    switch (errnum) {
    case -EINVAL: return "invalid argument";
    case -ENOENT: return "not found";
    case -EACCES: return "not writable";
    case -EIO: return "missing target storage";
    case -EBADF: return "invalid type";
    case -ERANGE: return "value out of range";
    case -ENOMEM: return "out of memory";
    case -EISCONN: return "queue already allocated";
    case -EEXIST: return "name exists";
    case -EFAULT: return "shared memory not mapped";
    case -EMFILE: return "too many modules";
    case -EPROTO: return "hal data version mismatch";
    case -EPERM: return "hal is locked";
    case -ENOEXEC: return "missing constructor";
    default: return "unknown error";
    }
}

/* The RTAPI realtime type of this host. */
int hal_get_realtime_type(void)
{
    return rtapi_get_realtime_type();
}
