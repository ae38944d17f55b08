/* lbp16.c: LBP16 command words and datagram assembly/decoding (no I/O). */
#include <string.h>
#include "rtapi_errno.h"
#include "lbp16.h"

/* Element size code: 0 = 8, 1 = 16, 2 = 32, 3 = 64 bit. */
static int size_code(int elem_bytes)
{
    return elem_bytes == 1 ? 0 : elem_bytes == 2 ? 1 : elem_bytes == 4 ? 2 : 3;
}

/* Build a command word. */
uint16_t lbp16_command(bool write, bool has_addr, int space, int elem_bytes, bool inc, int count)
{
    return (uint16_t)((write ? LBP16_CMD_WRITE : 0) | (has_addr ? LBP16_CMD_ADDR : 0) |
                      ((unsigned)space & 7) << LBP16_CMD_SPACE_SHIFT |
                      (unsigned)size_code(elem_bytes) << LBP16_CMD_SIZE_SHIFT |
                      (inc ? LBP16_CMD_INC : 0) | ((unsigned)count & LBP16_CMD_COUNT_MASK));
}

/* Forget everything queued in a packet. */
void lbp16_reset(lbp16_packet_t *p)
{
    p->len = 0;
    p->reply_len = 0;
}

/* Append a little-endian 16-bit word. */
static void put16(lbp16_packet_t *p, uint16_t v)
{
    p->data[p->len++] = (uint8_t)(v & 0xFF);
    p->data[p->len++] = (uint8_t)(v >> 8);
}

/* Read command + address; the reply grows by count elements. */
int lbp16_add_read(lbp16_packet_t *p, int space, int elem_bytes, uint16_t addr, int count, bool inc)
{
    if (count < 1 || count > LBP16_MAX_COUNT || p->len + 4 > LBP16_MAX_PACKET ||
        p->reply_len + count * elem_bytes > LBP16_MAX_PACKET)
        return -ENOSPC;
    put16(p, lbp16_command(false, true, space, elem_bytes, inc, count));
    put16(p, addr);
    p->reply_len += count * elem_bytes;
    return 0;
}

/* Write command + address + data. */
int lbp16_add_write(lbp16_packet_t *p, int space, int elem_bytes, uint16_t addr, const void *data,
                    int count, bool inc)
{
    int bytes = count * elem_bytes;
    if (count < 1 || count > LBP16_MAX_COUNT || p->len + 4 + bytes > LBP16_MAX_PACKET)
        return -ENOSPC;
    put16(p, lbp16_command(true, true, space, elem_bytes, inc, count));
    put16(p, addr);
    memcpy(p->data + p->len, data, bytes);
    p->len += bytes;
    return 0;
}

/* Decode one command header (and its address when present). */
int lbp16_decode(const uint8_t *buf, int len, lbp16_cmd_t *cmd)
{
    if (len < 2)
        return -EINVAL;
    uint16_t w = (uint16_t)(buf[0] | buf[1] << 8);
    cmd->write = (w & LBP16_CMD_WRITE) != 0;
    cmd->has_addr = (w & LBP16_CMD_ADDR) != 0;
    cmd->info = (w & LBP16_CMD_INFO) != 0;
    cmd->space = (w >> LBP16_CMD_SPACE_SHIFT) & 7;
    cmd->elem_bytes = 1 << ((w >> LBP16_CMD_SIZE_SHIFT) & 3);
    cmd->inc = (w & LBP16_CMD_INC) != 0;
    cmd->count = w & LBP16_CMD_COUNT_MASK;
    if (cmd->count == 0)
        return -EINVAL;
    if (!cmd->has_addr)
        return 2;
    if (len < 4)
        return -EINVAL;
    cmd->addr = (uint16_t)(buf[2] | buf[3] << 8);
    return 4;
}
