/* canopen.h: CANopen (CiA 301) and CiA 402 numbers shared by the cia402 driver and its simulated drive. */
#ifndef CANOPEN_H
#define CANOPEN_H

#include <stdint.h>

/* One classic CAN frame (11-bit identifiers only). */
typedef struct {
    uint16_t id;       /* COB-ID, 0..0x7FF */
    uint8_t len;       /* data length 0..8 */
    uint8_t rtr;       /* remote request */
    uint8_t data[8];
} co_frame_t;

/* COB-ID function codes (bits 7..10) and the node id mask. */
#define CO_ID_MASK 0x7FFu
#define CO_NODE_MASK 0x7Fu
#define CO_FUNC_MASK 0x780u
#define CO_NMT 0x000u
#define CO_SYNC 0x080u
#define CO_EMCY 0x080u
#define CO_TPDO1 0x180u
#define CO_RPDO1 0x200u
#define CO_TPDO2 0x280u
#define CO_RPDO2 0x300u
#define CO_SDO_TX 0x580u      /* server (drive) -> client (master) */
#define CO_SDO_RX 0x600u      /* client -> server */
#define CO_HEARTBEAT 0x700u
#define CO_MAX_NODE 127

/* NMT commands (byte 0 of a frame to COB-ID 0). */
#define CO_NMT_START 0x01u
#define CO_NMT_STOP 0x02u
#define CO_NMT_PRE_OPERATIONAL 0x80u
#define CO_NMT_RESET_NODE 0x81u
#define CO_NMT_RESET_COMMUNICATION 0x82u

/* NMT states as heartbeats report them. */
#define CO_STATE_BOOTUP 0x00u
#define CO_STATE_STOPPED 0x04u
#define CO_STATE_OPERATIONAL 0x05u
#define CO_STATE_PRE_OPERATIONAL 0x7Fu

/* SDO command bytes (expedited transfers). */
#define CO_SDO_CCS_DOWNLOAD 0x20u      /* initiate download request, | 0x03 expedited+size, | (4-n)<<2 */
#define CO_SDO_CCS_UPLOAD 0x40u        /* initiate upload request */
#define CO_SDO_SCS_DOWNLOAD 0x60u      /* initiate download response */
#define CO_SDO_SCS_UPLOAD 0x40u        /* initiate upload response (| 0x03 expedited+size) */
#define CO_SDO_ABORT 0x80u
#define CO_SDO_EXPEDITED 0x02u
#define CO_SDO_SIZE_SET 0x01u

/* SDO abort codes used here. */
#define CO_ABORT_TIMEOUT 0x05040000u
#define CO_ABORT_COMMAND 0x05040001u
#define CO_ABORT_UNSUPPORTED_ACCESS 0x06010000u
#define CO_ABORT_WRITE_ONLY 0x06010001u
#define CO_ABORT_READ_ONLY 0x06010002u
#define CO_ABORT_NO_OBJECT 0x06020000u
#define CO_ABORT_NOT_MAPPABLE 0x06040041u
#define CO_ABORT_PDO_TOO_LONG 0x06040042u
#define CO_ABORT_LENGTH 0x06070010u
#define CO_ABORT_NO_SUBINDEX 0x06090011u
#define CO_ABORT_VALUE_RANGE 0x06090030u
#define CO_ABORT_GENERAL 0x08000000u
#define CO_ABORT_DEVICE_STATE 0x08000022u

/* Object dictionary entries (CiA 301). */
#define CO_OBJ_ERROR_REGISTER 0x1001u
#define CO_OBJ_SYNC_COB_ID 0x1005u
#define CO_OBJ_CYCLE_PERIOD 0x1006u
#define CO_OBJ_HEARTBEAT_TIME 0x1017u
#define CO_OBJ_RPDO_COMM 0x1400u
#define CO_OBJ_RPDO_MAP 0x1600u
#define CO_OBJ_TPDO_COMM 0x1800u
#define CO_OBJ_TPDO_MAP 0x1A00u
#define CO_PDO_INVALID 0x80000000u      /* COB-ID bit 31: PDO does not exist / disabled */
#define CO_PDO_SYNC_EVERY 1u            /* transmission type: every SYNC */

/* CiA 402 objects. */
#define CIA402_CONTROLWORD 0x6040u
#define CIA402_STATUSWORD 0x6041u
#define CIA402_MODE 0x6060u
#define CIA402_MODE_DISPLAY 0x6061u
#define CIA402_POSITION_ACTUAL 0x6064u
#define CIA402_VELOCITY_ACTUAL 0x606Cu
#define CIA402_TORQUE_ACTUAL 0x6077u
#define CIA402_TARGET_POSITION 0x607Au
#define CIA402_INTERPOLATION_PERIOD 0x60C2u
#define CIA402_ERROR_CODE 0x603Fu
#define CIA402_MODE_CSP 8

/* A PDO mapping entry: index << 16 | sub << 8 | bits. */
#define CO_MAP(index, sub, bits) (((uint32_t)(index) << 16) | ((uint32_t)(sub) << 8) | (uint32_t)(bits))

/* Little-endian helpers. */
static inline uint16_t co_get16(const uint8_t *p) { return (uint16_t)(p[0] | p[1] << 8); }
static inline uint32_t co_get32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline void co_put16(uint8_t *p, uint16_t v) { p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); }
static inline void co_put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

#endif
