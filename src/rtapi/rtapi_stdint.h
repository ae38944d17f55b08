/* rtapi_stdint.h: fixed-width integer types for realtime code, with LinuxCNC's rtapi_ names. */
#ifndef RTAPI_STDINT_H
#define RTAPI_STDINT_H
#include <stdint.h>
#include <inttypes.h>

typedef int8_t rtapi_s8;
typedef int16_t rtapi_s16;
typedef int32_t rtapi_s32;
typedef int64_t rtapi_s64;
typedef uint8_t rtapi_u8;
typedef uint16_t rtapi_u16;
typedef uint32_t rtapi_u32;
typedef uint64_t rtapi_u64;
typedef intptr_t rtapi_intptr_t;
typedef uintptr_t rtapi_uintptr_t;

#define RTAPI_INT8_MIN INT8_MIN
#define RTAPI_INT8_MAX INT8_MAX
#define RTAPI_UINT8_MAX UINT8_MAX
#define RTAPI_INT16_MIN INT16_MIN
#define RTAPI_INT16_MAX INT16_MAX
#define RTAPI_UINT16_MAX UINT16_MAX
#define RTAPI_INT32_MIN INT32_MIN
#define RTAPI_INT32_MAX INT32_MAX
#define RTAPI_UINT32_MAX UINT32_MAX
#define RTAPI_INT64_MIN INT64_MIN
#define RTAPI_INT64_MAX INT64_MAX
#define RTAPI_UINT64_MAX UINT64_MAX
#define RTAPI_INTPTR_MIN INTPTR_MIN
#define RTAPI_INTPTR_MAX INTPTR_MAX
#define RTAPI_UINTPTR_MAX UINTPTR_MAX
#endif
