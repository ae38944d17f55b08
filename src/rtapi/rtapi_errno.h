/* rtapi_errno.h: errno constants for realtime code. */
#ifndef RTAPI_ERRNO_H
#define RTAPI_ERRNO_H
#include <errno.h>
#endif
