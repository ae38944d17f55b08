/* lbp16.h: Mesa's LBP16 protocol over UDP: command words and packet building/decoding (pure, shared by hm2_eth and mesa-sim). */
#ifndef LBP16_H
#define LBP16_H

#include <stdbool.h>
#include <stdint.h>

#define LBP16_UDP_PORT 27181
#define LBP16_MAX_PACKET 1400
#define LBP16_MAX_COUNT 127

#define LBP16_CMD_WRITE 0x8000u
#define LBP16_CMD_ADDR 0x4000u
#define LBP16_CMD_INFO 0x2000u
#define LBP16_CMD_SPACE_SHIFT 10
#define LBP16_CMD_SIZE_SHIFT 8
#define LBP16_CMD_INC 0x0080u
#define LBP16_CMD_COUNT_MASK 0x007Fu

/* Memory spaces. */
enum {
    LBP16_SPACE_HOSTMOT2 = 0,
    LBP16_SPACE_ETH_CHIP = 1,
    LBP16_SPACE_ETH_EEPROM = 2,
    LBP16_SPACE_FPGA_FLASH = 3,
    LBP16_SPACE_TIMER = 4,
    LBP16_SPACE_COMM_STATUS = 6,
    LBP16_SPACE_BOARD_INFO = 7,
};

/* Addresses used by hm2_eth. */
#define LBP16_ADDR_MAC 0x0002            /* space 2, three 16-bit words */
#define LBP16_ADDR_RX_UDP_COUNT 0x0008   /* space 6 */
#define LBP16_ADDR_READ_SEQ 0x0010       /* space 4: read then write sequence numbers */
#define LBP16_ADDR_WRITE_SEQ 0x0014
#define LBP16_BOARD_NAME_LEN 16

/* One decoded command. */
typedef struct {
    bool write, has_addr, info, inc;
    int space;
    int elem_bytes;          /* 1, 2, 4 or 8 */
    int count;               /* 1..127 */
    uint16_t addr;
} lbp16_cmd_t;

/* A datagram under construction, and how many reply bytes it asks for. */
typedef struct {
    uint8_t data[LBP16_MAX_PACKET];
    int len;
    int reply_len;
} lbp16_packet_t;

/* The 16-bit command word. */
uint16_t lbp16_command(bool write, bool has_addr, int space, int elem_bytes, bool inc, int count);
/* Empty a packet. */
void lbp16_reset(lbp16_packet_t *p);
/* Append a read of count elements at addr (with address, incrementing); -ENOSPC when full. */
int lbp16_add_read(lbp16_packet_t *p, int space, int elem_bytes, uint16_t addr, int count, bool inc);
/* Append a write of count elements from data (little-endian bytes); -ENOSPC when full. */
int lbp16_add_write(lbp16_packet_t *p, int space, int elem_bytes, uint16_t addr, const void *data,
                    int count, bool inc);
/* Decode the command at buf (len bytes left); returns header bytes used, or -EINVAL. */
int lbp16_decode(const uint8_t *buf, int len, lbp16_cmd_t *cmd);

#endif
