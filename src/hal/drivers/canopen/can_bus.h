/* can_bus.h: one SocketCAN interface opened for non-blocking, batched frame I/O. */
#ifndef CAN_BUS_H
#define CAN_BUS_H

#include <stdint.h>
#include <linux/can.h>
#include <sys/socket.h>
#include "canopen.h"

#define CAN_BUS_BATCH 32                 /* frames per recvmmsg/sendmmsg call */
#define CAN_BUS_NAME_LEN 16

/* An open interface and its transmit queue of one cycle. */
typedef struct {
    char name[CAN_BUS_NAME_LEN];
    int fd;
    struct can_frame tx[CAN_BUS_BATCH];
    int tx_count;
    uint32_t tx_dropped;                 /* frames the socket would not take */
    int last_errno;                      /* of the last failed send or receive, 0 = none */
} can_bus_t;

/* Open interface name, receiving only the standard-frame COB-IDs in ids[] (id_count 0: all); 0 or a negative errno
   with a message in why (interface missing or down, no SocketCAN, ...). */
int can_bus_open(can_bus_t *bus, const char *name, const uint16_t *ids, int id_count, char *why, int why_len);

/* Read up to max pending frames without waiting into frames[] (*valid of them are classic standard
   frames); returns how many the socket gave (max: call again) or a negative errno. */
int can_bus_receive(can_bus_t *bus, co_frame_t *frames, int max, int *valid);

/* Add a frame to this cycle's queue (frames past the batch size are counted as dropped). */
void can_bus_queue(can_bus_t *bus, const co_frame_t *f);

/* Send the queued frames with one call, without waiting; 0 or a negative errno. */
int can_bus_flush(can_bus_t *bus);

/* Close the socket. */
void can_bus_close(can_bus_t *bus);

#endif
