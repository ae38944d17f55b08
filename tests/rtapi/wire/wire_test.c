/* wire_test.c: unit test of the rtapi_app protocol encoder/decoder, incl. malformed input. */
#include <stdio.h>
#include <string.h>
#include "rtapi_wire.h"

static char store[RTAPI_WIRE_MAX];
static char *argv_out[RTAPI_WIRE_MAX_ARGS + 1];

/* Decode msg and print the outcome. */
static void try_request(const char *what, const unsigned char *msg, size_t len)
{
    int argc = rtapi_wire_decode_request(msg, len, store, argv_out, RTAPI_WIRE_MAX_ARGS);

    printf("%s: %d", what, argc);
    for (int i = 0; i < argc; i++)
        printf(" [%s]", argv_out[i]);
    printf("\n");
}

/* Round trip and corruptions of a request. */
static void requests(void)
{
    const char *argv[] = { "load", "siggen", "num_chan=2", "" };
    unsigned char buf[256], bad[256];
    int len = rtapi_wire_encode_request(4, argv, buf, sizeof buf);

    printf("encoded length %d\n", len);
    try_request("round trip", buf, (size_t)len);
    try_request("truncated", buf, (size_t)len - 1);
    try_request("short header", buf, 3);
    memcpy(bad, buf, (size_t)len);
    bad[2] = 5;
    try_request("argc too big", bad, (size_t)len);
    memcpy(bad, buf, (size_t)len);
    bad[4] = 200;
    try_request("arg overruns", bad, (size_t)len);
    memcpy(bad, buf, (size_t)len);
    bad[7] = 0;
    try_request("NUL inside arg", bad, (size_t)len);
    memcpy(bad, buf, (size_t)len);
    bad[0] = (unsigned char)(len + 1);
    bad[len] = 'x';
    try_request("trailing byte", bad, (size_t)len + 1);
    printf("too many args: %d\n",
           rtapi_wire_encode_request(RTAPI_WIRE_MAX_ARGS + 1, argv, buf, sizeof buf));
    printf("too long: %d\n", rtapi_wire_encode_request(4, argv, buf, 20));
}

/* Round trip and corruptions of a reply. */
static void replies(void)
{
    unsigned char buf[64];
    char text[8];
    int result = 0;
    int len = rtapi_wire_encode_reply(-22, "hello world", buf, sizeof buf);
    int rc = rtapi_wire_decode_reply(buf, (size_t)len, &result, text, sizeof text);

    printf("reply: len %d rc %d result %d text [%s]\n", len, rc, result, text);
    buf[6] = 40;
    printf("reply bad text length: %d\n",
           rtapi_wire_decode_reply(buf, (size_t)len, &result, text, sizeof text));
    printf("reply too short: %d\n", rtapi_wire_decode_reply(buf, 5, &result, text, sizeof text));
}

/* Run the request and reply checks. */
int main(void)
{
    requests();
    replies();
    return 0;
}
