/* hm2_access.c: register access through the board driver's ops table (direct or queued). */
#include "hm2.h"

/* Blocking read of size bytes at addr. 0 or -errno. */
int hm2_read(hm2_board_t *hm2, uint32_t addr, void *buf, int size)
{
    return hm2->llio->ops->read(hm2->llio, addr, buf, size);
}

/* Blocking (or, in the cycle, driver-queued) write of size bytes at addr. 0 or -errno. */
int hm2_write(hm2_board_t *hm2, uint32_t addr, const void *buf, int size)
{
    return hm2->llio->ops->write(hm2->llio, addr, buf, size);
}

/* Write sent with the cycle's write packet when the driver queues, else at once. */
int hm2_queue_write(hm2_board_t *hm2, uint32_t addr, const void *buf, int size)
{
    const hm2_llio_ops_t *ops = hm2->llio->ops;
    if (ops->queue_write)
        return ops->queue_write(hm2->llio, addr, buf, size);
    return ops->write(hm2->llio, addr, buf, size);
}

/* Read answered with the cycle's read packet when the driver queues, else at once. */
int hm2_queue_read(hm2_board_t *hm2, uint32_t addr, void *buf, int size)
{
    const hm2_llio_ops_t *ops = hm2->llio->ops;
    if (ops->queue_read)
        return ops->queue_read(hm2->llio, addr, buf, size);
    return ops->read(hm2->llio, addr, buf, size);
}
