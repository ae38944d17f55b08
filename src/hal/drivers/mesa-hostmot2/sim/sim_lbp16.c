/* sim_lbp16.c: answer LBP16 datagrams like a Mesa Ethernet card (spaces 0, 2, 4, 6, 7). */
#include <string.h>
#include "sim_card.h"
#include "../lbp16.h"

#define RX_PACKET_WORD 4        /* status words: RX packet count */
#define RX_UDP_WORD 5
#define PARSE_ERRORS_WORD 1

/* Byte of a little-endian memory area, 0 outside it. */
static uint8_t area_byte(const uint8_t *area, int size, int at)
{
    return at >= 0 && at < size ? area[at] : 0;
}

/* Bytes of a read from one space into out. */
static void space_read(sim_card_t *c, int space, uint16_t addr, int bytes, uint8_t *out)
{
    if (space == LBP16_SPACE_HOSTMOT2) {
        for (int i = 0; i < bytes; i += 4) {
            uint32_t v = sim_reg_read(c, (uint16_t)((addr + i) & ~3));
            for (int k = 0; k < 4 && i + k < bytes; k++)
                out[i + k] = (uint8_t)(v >> (8 * k));
        }
        return;
    }
    uint8_t eeprom[8] = {0, 0, c->mac[5], c->mac[4], c->mac[3], c->mac[2], c->mac[1], c->mac[0]};
    uint8_t info[LBP16_BOARD_NAME_LEN + 6] = {0};
    strncpy((char *)info, c->board->name, LBP16_BOARD_NAME_LEN);
    info[LBP16_BOARD_NAME_LEN] = 3;   /* LBP16 version */
    for (int i = 0; i < bytes; i++) {
        int at = addr + i;
        switch (space) {
        case LBP16_SPACE_ETH_EEPROM: out[i] = area_byte(eeprom, sizeof(eeprom), at); break;
        case LBP16_SPACE_TIMER: out[i] = area_byte(c->scratch, sizeof(c->scratch), at); break;
        case LBP16_SPACE_COMM_STATUS:
            out[i] = area_byte((const uint8_t *)c->status_words, sizeof(c->status_words), at);
            break;
        case LBP16_SPACE_BOARD_INFO: out[i] = area_byte(info, sizeof(info), at); break;
        default: out[i] = 0;
        }
    }
}

/* Bytes of a write into one space (space 0 by whole registers). */
static void space_write(sim_card_t *c, int space, uint16_t addr, int bytes, const uint8_t *in)
{
    if (space == LBP16_SPACE_HOSTMOT2) {
        for (int i = 0; i + 4 <= bytes; i += 4) {
            uint32_t v = (uint32_t)in[i] | (uint32_t)in[i + 1] << 8 | (uint32_t)in[i + 2] << 16 |
                         (uint32_t)in[i + 3] << 24;
            sim_reg_write(c, (uint16_t)(addr + i), v);
        }
    } else if (space == LBP16_SPACE_TIMER) {
        for (int i = 0; i < bytes; i++)
            if (addr + i < (int)sizeof(c->scratch))
                c->scratch[addr + i] = in[i];
    }
}

/* One command's data: element by element, incrementing or not. */
static void run_command(sim_card_t *c, const lbp16_cmd_t *cmd, uint16_t *addr, const uint8_t *in,
                        uint8_t *out)
{
    for (int e = 0; e < cmd->count; e++) {
        int off = e * cmd->elem_bytes;
        if (cmd->write)
            space_write(c, cmd->space, *addr, cmd->elem_bytes, in + off);
        else
            space_read(c, cmd->space, *addr, cmd->elem_bytes, out + off);
        if (cmd->inc)
            *addr = (uint16_t)(*addr + cmd->elem_bytes);
    }
}

/* Process every command of a datagram; returns the reply length, or -1 for a malformed one. */
int sim_handle_datagram(sim_card_t *c, const uint8_t *in, int len, uint8_t *out, int cap)
{
    int pos = 0, reply = 0;
    c->status_words[RX_PACKET_WORD]++;
    c->status_words[RX_UDP_WORD]++;
    while (pos < len) {
        lbp16_cmd_t cmd;
        int n = lbp16_decode(in + pos, len - pos, &cmd);
        int bytes = cmd.count * cmd.elem_bytes;
        if (n < 0 || (cmd.write && pos + n + bytes > len) || (!cmd.write && reply + bytes > cap)) {
            c->status_words[PARSE_ERRORS_WORD]++;
            return -1;
        }
        pos += n;
        uint16_t addr = cmd.has_addr ? cmd.addr : c->space_addr[cmd.space];
        run_command(c, &cmd, &addr, in + pos, out + reply);
        c->space_addr[cmd.space] = addr;
        if (cmd.write)
            pos += bytes;
        else
            reply += bytes;
    }
    return reply;
}
