/* hm2_sserial_proto.h: the Smart Serial (SSLBP) register commands and discovery record layout,
   shared by the hostmot2 driver and the simulated card so both speak one definition. */
#ifndef HM2_SSERIAL_PROTO_H
#define HM2_SSERIAL_PROTO_H

/* Module registers (index r: base + r*RegisterStride + port*InstanceStride [+ 4*channel]). */
enum {
    SSLBP_REG_COMMAND = 0,      /* per port */
    SSLBP_REG_DATA = 1,         /* per port: command result */
    SSLBP_REG_CS = 2,           /* per channel: control/status */
    SSLBP_REG_INTERFACE0 = 3,   /* per channel: process data, remote reads (user0) */
    SSLBP_REG_INTERFACE1 = 4,   /* user1: the remote's name at setup */
    SSLBP_REG_INTERFACE2 = 5,   /* user2: PTOC (low 16) and GTOC (high 16) addresses */
};
#define SSLBP_V0_REGISTERS 6
#define SSLBP_V0_INTERFACE_REGS 3
#define SSLBP_MAX_INTERFACE_REGS 7
#define SSLBP_INSTANCE_STRIDE 0x40
#define SSLBP_MULTIPLE_REGS 0x3C
#define SSLBP_MAX_CHANNELS 8

/* Commands written to the command register; it reads back 0 when the command is done. */
#define SSLBP_CMD_RESET 0x4000u
#define SSLBP_CMD_CLEAR 0x0001u
#define SSLBP_CMD_READ_LOCAL 0x2000u    /* | local address: the byte lands in the data register */
#define SSLBP_CMD_WRITE_LOCAL 0xA000u
#define SSLBP_CMD_START_SETUP 0x0F00u   /* | channel mask */
#define SSLBP_CMD_START_NORMAL 0x0900u  /* | channel mask */
#define SSLBP_CMD_STOP_ALL 0x0800u
#define SSLBP_CMD_DOIT 0x1000u          /* | channel mask: one process-data (or remote) transfer */
#define SSLBP_CMD_IGNORED 0x80000000u   /* bit 31: the firmware ignores the write */
#define SSLBP_CMD_MASK 0x000000FFu

/* Local (SSLBP processor) addresses read with SSLBP_CMD_READ_LOCAL. */
#define SSLBP_LOCAL_VERSION 0x03

/* After a start or do-it the data register's low byte has a bit set per channel that failed. */
#define SSLBP_DATA_FAIL_MASK 0xFFu

/* Channel CS register: written before a start (mode << 24) or a remote access (command << 24). */
#define SSLBP_CS_MODE_SHIFT 24
#define SSLBP_CS_REMOTE_READ 0x4C000000u   /* | remote address: 4 bytes into interface0 */
#define SSLBP_CS_REMOTE_WRITE 0x6C000000u  /* | remote address: interface0's 4 bytes to it */
#define SSLBP_CS_ADDR_MASK 0xFFFFu
/* CS read back: low byte = remote status (0 = ok), next byte = link status, byte 2 = protocol. */
#define SSLBP_CS_STATUS(cs) ((cs) & 0xFFu)
#define SSLBP_CS_LINK(cs) (((cs) >> 8) & 0xFFu)
#define SSLBP_CS_PROTOCOL(cs) (((cs) >> 16) & 0xFFu)
enum { SSLBP_LINK_OK = 0, SSLBP_LINK_TIMEOUT = 1, SSLBP_LINK_CRC = 2 };
enum { SSLBP_STATUS_WATCHDOG = 0x01, SSLBP_STATUS_FIELD_POWER = 0x02 };

/* Discovery records in remote memory; each TOC is a 0-terminated list of 16-bit addresses. */
#define SSLBP_REC_PROCESS_DATA 0xA0
#define SSLBP_REC_MODE 0xB0
#define SSLBP_REC_NAME_MAX 32
/* Process data record: type, bits, data type, direction, ParmMin/ParmMax (float LE),
   ParmAddr (u16 LE), then the unit and the name, each 0-terminated. */
enum {
    SSLBP_PD_TYPE = 0, SSLBP_PD_BITS = 1, SSLBP_PD_DATA_TYPE = 2, SSLBP_PD_DIR = 3,
    SSLBP_PD_MIN = 4, SSLBP_PD_MAX = 8, SSLBP_PD_ADDR = 12, SSLBP_PD_STRINGS = 14,
};
/* Mode record: type, index, kind (0 hardware, 1 software), unused, name (0-terminated). */
enum { SSLBP_MODE_INDEX = 1, SSLBP_MODE_KIND = 2, SSLBP_MODE_NAME = 4 };
enum { SSLBP_MODE_HARDWARE = 0, SSLBP_MODE_SOFTWARE = 1 };

/* Data types and directions. */
enum {
    SSLBP_TYPE_PAD = 0x00, SSLBP_TYPE_BITS = 0x01, SSLBP_TYPE_UNSIGNED = 0x02,
    SSLBP_TYPE_SIGNED = 0x03, SSLBP_TYPE_NONVOL_UNSIGNED = 0x04, SSLBP_TYPE_NONVOL_SIGNED = 0x05,
    SSLBP_TYPE_STREAM = 0x06, SSLBP_TYPE_BOOLEAN = 0x07, SSLBP_TYPE_ENCODER = 0x08,
    SSLBP_TYPE_FLOAT = 0x10, SSLBP_TYPE_ENCODER_H = 0x18,
};
enum { SSLBP_DIR_IN = 0x00, SSLBP_DIR_IO = 0x40, SSLBP_DIR_OUT = 0x80 };

#endif
