/* rtapi_wire.c: rtapi_app protocol framing over the instance's abstract UNIX socket. */
#include <errno.h>
#include <poll.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include "rtapi_instance.h"
#include "rtapi_wire.h"

/* Store a little-endian u16. */
static void put16(unsigned char *p, unsigned v)
{
    p[0] = v & 0xff;
    p[1] = (v >> 8) & 0xff;
}

/* Load a little-endian u16. */
static unsigned get16(const unsigned char *p)
{
    return p[0] | (p[1] << 8);
}

/* Encode argv as a request frame. */
int rtapi_wire_encode_request(int argc, const char *const argv[], unsigned char *buf,
                              size_t size)
{
    size_t pos = 4;

    if (argc < 0 || argc > RTAPI_WIRE_MAX_ARGS)
        return -E2BIG;
    for (int i = 0; i < argc; i++) {
        size_t len = strlen(argv[i]);
        if (pos + 2 + len > size || pos + 2 + len > RTAPI_WIRE_MAX)
            return -E2BIG;
        put16(buf + pos, (unsigned)len);
        memcpy(buf + pos + 2, argv[i], len);
        pos += 2 + len;
    }
    put16(buf, (unsigned)pos);
    put16(buf + 2, (unsigned)argc);
    return (int)pos;
}

/* Decode and validate every length field of a request frame. */
int rtapi_wire_decode_request(const unsigned char *msg, size_t len, char *store,
                              char **argv, int max_args)
{
    size_t pos = 4;
    unsigned argc;

    if (len < 4 || get16(msg) != len)
        return -EPROTO;
    argc = get16(msg + 2);
    if ((int)argc > max_args)
        return -EPROTO;
    for (unsigned i = 0; i < argc; i++) {
        size_t alen;
        if (pos + 2 > len)
            return -EPROTO;
        alen = get16(msg + pos);
        if (pos + 2 + alen > len || memchr(msg + pos + 2, 0, alen))
            return -EPROTO;
        memcpy(store, msg + pos + 2, alen);
        store[alen] = '\0';
        argv[i] = store;
        store += alen + 1;
        pos += 2 + alen;
    }
    if (pos != len)
        return -EPROTO;
    argv[argc] = NULL;
    return (int)argc;
}

/* Encode a reply frame (text truncated to fit). */
int rtapi_wire_encode_reply(int result, const char *text, unsigned char *buf, size_t size)
{
    size_t tlen = text ? strlen(text) : 0;
    uint32_t r = (uint32_t)result;

    if (size > RTAPI_WIRE_MAX)
        size = RTAPI_WIRE_MAX;
    if (8 + tlen > size)
        tlen = size - 8;
    put16(buf + 2, r & 0xffff);
    put16(buf + 4, r >> 16);
    put16(buf + 6, (unsigned)tlen);
    memcpy(buf + 8, text, tlen);
    put16(buf, (unsigned)(8 + tlen));
    return (int)(8 + tlen);
}

/* Decode and validate a reply frame. */
int rtapi_wire_decode_reply(const unsigned char *msg, size_t len, int *result, char *text,
                            size_t text_size)
{
    size_t tlen;

    if (len < 8 || get16(msg) != len)
        return -EPROTO;
    tlen = get16(msg + 6);
    if (8 + tlen != len)
        return -EPROTO;
    *result = (int)(uint32_t)(get16(msg + 2) | ((uint32_t)get16(msg + 4) << 16));
    if (text_size > 0) {
        size_t n = tlen < text_size - 1 ? tlen : text_size - 1;
        memcpy(text, msg + 8, n);
        text[n] = '\0';
    }
    return 0;
}

/* Read exactly len bytes, waiting at most timeout_ms for each chunk. */
static int read_full(int fd, unsigned char *buf, size_t len, int timeout_ms)
{
    size_t got = 0;

    while (got < len) {
        struct pollfd pfd = { fd, POLLIN, 0 };
        int rc = poll(&pfd, 1, timeout_ms > 0 ? timeout_ms : -1);
        ssize_t n;
        if (rc < 0 && errno == EINTR)
            continue;
        if (rc < 0)
            return -errno;
        if (rc == 0)
            return -ETIMEDOUT;
        n = read(fd, buf + got, len - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return -errno;
        if (n == 0)
            return -ECONNRESET;
        got += (size_t)n;
    }
    return 0;
}

/* Receive one frame, validating its total length before reading the rest. */
int rtapi_wire_recv(int fd, unsigned char *buf, size_t size, int timeout_ms)
{
    unsigned total;
    int rc = read_full(fd, buf, 2, timeout_ms);

    if (rc < 0)
        return rc;
    total = get16(buf);
    if (total < 4 || total > size)
        return -EPROTO;
    rc = read_full(fd, buf + 2, total - 2, timeout_ms);
    return rc < 0 ? rc : (int)total;
}

/* Send a whole frame. */
int rtapi_wire_send(int fd, const unsigned char *buf, size_t len)
{
    while (len > 0) {
        ssize_t n = send(fd, buf, len, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return -errno;
        buf += n;
        len -= (size_t)n;
    }
    return 0;
}

/* Fill an abstract address for this instance; returns its length or -ENAMETOOLONG. */
static int socket_address(struct sockaddr_un *addr)
{
    int len;

    memset(addr, 0, sizeof *addr);
    addr->sun_family = AF_UNIX;
    if (rtapi_instance() < 0)
        return -EINVAL;
    len = rtapi_instance_socket_name(addr->sun_path + 1, sizeof addr->sun_path - 1);
    if (len < 0)
        return -ENAMETOOLONG;
    return (int)(offsetof(struct sockaddr_un, sun_path) + 1 + len);
}

/* Opens a socket on this instance's address and connects (listen_on_it=0) or binds and listens. */
static int socket_open(int listen_on_it)
{
    struct sockaddr_un addr;
    int len = socket_address(&addr);
    int fd, rc;

    if (len < 0)
        return len;
    fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return -errno;
    if (listen_on_it)
        rc = bind(fd, (struct sockaddr *)&addr, (socklen_t)len) != 0 || listen(fd, 16) != 0;
    else
        rc = connect(fd, (struct sockaddr *)&addr, (socklen_t)len) != 0;
    if (rc) {
        int err = errno;
        close(fd);
        return -err;
    }
    return fd;
}

/* Connect to this instance's master. */
int rtapi_wire_connect(void)
{
    return socket_open(0);
}

/* Become this instance's master socket (fails when one is bound). */
int rtapi_wire_listen(void)
{
    return socket_open(1);
}
