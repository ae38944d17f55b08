/* rtapi_atomic.h: C11 atomics for realtime code (std::atomic in C++). */
#ifndef RTAPI_ATOMIC_H
#define RTAPI_ATOMIC_H
#ifdef __cplusplus
#include <atomic>
#else
#include <stdatomic.h>
#endif
#endif
