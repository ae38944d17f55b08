/* rtapi_stdint.h: fixed-width integer types for realtime code. */
#ifndef RTAPI_STDINT_H
#define RTAPI_STDINT_H
#include <stdint.h>
#include <inttypes.h>
#endif
