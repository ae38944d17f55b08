/* rtapi_io.h: raw x86 port I/O and I/O region requests. */
#ifndef RTAPI_IO_H
#define RTAPI_IO_H
#include "rtapi.h"

RTAPI_BEGIN_DECLS
unsigned char rtapi_inb(unsigned int port);
unsigned short rtapi_inw(unsigned int port);
unsigned int rtapi_inl(unsigned int port);
void rtapi_outb(unsigned char byte, unsigned int port);
void rtapi_outw(unsigned short word, unsigned int port);
void rtapi_outl(unsigned int word, unsigned int port);
/* Gain access to ports base..base+size-1: non-NULL on success, NULL on failure. */
void *rtapi_request_region(unsigned long base, unsigned long size, const char *name);
/* Give up access to a port range. */
void rtapi_release_region(unsigned long base, unsigned long size);
RTAPI_END_DECLS
#endif
