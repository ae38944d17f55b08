/* rtapi_ctype.h: character classification for realtime code. */
#ifndef RTAPI_CTYPE_H
#define RTAPI_CTYPE_H
#include <ctype.h>
#endif
