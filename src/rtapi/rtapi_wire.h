/* rtapi_wire.h: the rtapi_app socket protocol (framing, encode/decode, timed I/O). */
#ifndef RTAPI_WIRE_H
#define RTAPI_WIRE_H

#include <stddef.h>

/* Largest message: the u16 total length (which counts itself) bounds it. */
#define RTAPI_WIRE_MAX 65535
#define RTAPI_WIRE_MAX_ARGS 1024

/* Request: u16 total, u16 argc, argc x (u16 len, bytes). Returns length or -E2BIG. */
int rtapi_wire_encode_request(int argc, const char *const argv[], unsigned char *buf,
                              size_t size);
/* Decode a request of len bytes; strings are copied NUL-terminated into store
   (needs len bytes) and argv[] (max_args entries + NULL). Returns argc or -EPROTO. */
int rtapi_wire_decode_request(const unsigned char *msg, size_t len, char *store,
                              char **argv, int max_args);
/* Reply: u16 total, s32 result, u16 text length, text. Returns length. */
int rtapi_wire_encode_reply(int result, const char *text, unsigned char *buf, size_t size);
/* Decode a reply; text is NUL-terminated (truncated to text_size). 0 or -EPROTO. */
int rtapi_wire_decode_reply(const unsigned char *msg, size_t len, int *result, char *text,
                            size_t text_size);
/* Read one framed message (timeout_ms per read, 0 = none); length or -errno. */
int rtapi_wire_recv(int fd, unsigned char *buf, size_t size, int timeout_ms);
/* Write all len bytes (no SIGPIPE); 0 or -errno. */
int rtapi_wire_send(int fd, const unsigned char *buf, size_t len);
/* Connect to this instance's master socket; fd or -errno. */
int rtapi_wire_connect(void);
/* Bind and listen on this instance's master socket; fd, -EADDRINUSE or -errno. */
int rtapi_wire_listen(void);

#endif
