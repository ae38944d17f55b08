/* canopen_sdo.h: the master's side of expedited SDO downloads (one object write per request). */
#ifndef CANOPEN_SDO_H
#define CANOPEN_SDO_H

#include "canopen.h"

/* One object write: size is 1, 2 or 4 bytes. */
typedef struct {
    uint16_t index;
    uint8_t sub;
    uint8_t size;
    uint32_t value;
} co_sdo_write_t;

/* What a frame from the drive's SDO server means for a pending write. */
typedef enum {
    CO_SDO_REPLY_UNRELATED = 0, /* not an answer to this request (other object) */
    CO_SDO_REPLY_DONE,          /* download confirmed */
    CO_SDO_REPLY_ABORT,         /* the drive refused: *abort_code says why */
    CO_SDO_REPLY_MALFORMED      /* not a valid SDO answer */
} co_sdo_reply_t;

/* The download request for w to node. */
void co_sdo_download_frame(uint8_t node, const co_sdo_write_t *w, co_frame_t *f);

/* Judge a frame received on the node's SDO response COB-ID. */
co_sdo_reply_t co_sdo_download_reply(const co_frame_t *f, const co_sdo_write_t *w, uint32_t *abort_code);

/* A short description of an SDO abort code. */
const char *co_abort_text(uint32_t code);

#endif
