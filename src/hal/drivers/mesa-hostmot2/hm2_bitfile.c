/* hm2_bitfile.c: Xilinx .bit file parsing and FPGA part matching (pure, unit-tested). */
#include <ctype.h>
#include <string.h>
#include <strings.h>
#include "rtapi_errno.h"
#include "hm2_firmware.h"

#define BITFILE_MAGIC_LEN 13

static const uint8_t bitfile_magic[BITFILE_MAGIC_LEN] = {
    0x00, 0x09, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x00, 0x00, 0x01};

/* Copy a length-prefixed string section into dst. */
static void copy_section(char *dst, size_t dstlen, const uint8_t *src, size_t len)
{
    size_t n = len < dstlen - 1 ? len : dstlen - 1;
    memcpy(dst, src, n);
    dst[n] = '\0';
}

/* Sections 'a' design, 'b' part, 'c' date, 'd' time (u16 length), 'e' bits (u32 length). */
int hm2_bitfile_parse(const uint8_t *data, size_t size, hm2_bitfile_t *bf)
{
    memset(bf, 0, sizeof(*bf));
    if (size < BITFILE_MAGIC_LEN || memcmp(data, bitfile_magic, BITFILE_MAGIC_LEN) != 0)
        return -EINVAL;
    size_t at = BITFILE_MAGIC_LEN;
    while (at < size) {
        uint8_t key = data[at++];
        if (key == 'e') {
            if (at + 4 > size)
                return -EINVAL;
            size_t len = (size_t)data[at] << 24 | (size_t)data[at + 1] << 16 |
                         (size_t)data[at + 2] << 8 | data[at + 3];
            at += 4;
            if (len > size - at)
                return -EINVAL;
            bf->bits = data + at;
            bf->size = len;
            return bf->part[0] ? 0 : -EINVAL;
        }
        if (key < 'a' || key > 'd' || at + 2 > size)
            return -EINVAL;
        size_t len = (size_t)data[at] << 8 | data[at + 1];
        at += 2;
        if (len > size - at)
            return -EINVAL;
        if (key == 'a')
            copy_section(bf->design, sizeof(bf->design), data + at, len);
        if (key == 'b')
            copy_section(bf->part, sizeof(bf->part), data + at, len);
        at += len;
    }
    return -EINVAL;
}

/* Lower-case copy without a leading "xc" (Xilinx prefix). */
static void normalise_part(const char *in, char *out, size_t len)
{
    if (strncasecmp(in, "xc", 2) == 0)
        in += 2;
    size_t i = 0;
    for (; in[i] && i < len - 1; i++)
        out[i] = (char)tolower((unsigned char)in[i]);
    out[i] = '\0';
}

/* The board part is a prefix of the bitfile part (package and speed grade may follow). */
int hm2_fpga_part_matches(const char *board_part, const char *bitfile_part)
{
    char a[64], b[64];
    normalise_part(board_part, a, sizeof(a));
    normalise_part(bitfile_part, b, sizeof(b));
    return strncmp(a, b, strlen(a)) == 0 || strncmp(a, b, strlen(b)) == 0;
}

