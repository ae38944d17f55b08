/* rtapi_byteorder.h: host byte order as RTAPI_BIG_ENDIAN / RTAPI_LITTLE_ENDIAN. */
#ifndef RTAPI_BYTEORDER_H
#define RTAPI_BYTEORDER_H
#include <endian.h>
#if __BYTE_ORDER == __BIG_ENDIAN
#define RTAPI_BIG_ENDIAN 1
#define RTAPI_LITTLE_ENDIAN 0
#else
#define RTAPI_BIG_ENDIAN 0
#define RTAPI_LITTLE_ENDIAN 1
#endif
#define RTAPI_FLOAT_BIG_ENDIAN RTAPI_BIG_ENDIAN
#endif
