/* rtapi_bool.h: bool for realtime code (C and C++). */
#ifndef RTAPI_BOOL_H
#define RTAPI_BOOL_H
#ifndef __cplusplus
#include <stdbool.h>
#endif
#endif
