/* hm2_tram.c: the per-cycle read and write regions ("translation RAM") and their transfer. */
#include <stdlib.h>
#include "rtapi_errno.h"
#include "hm2.h"

/* Add a region to a list; the buffer pointer is filled by hm2_allocate_tram_regions. */
static int add_region(hm2_board_t *hm2, hm2_tram_region_t *list, int *count, uint32_t addr,
                      int size, uint32_t **buffer)
{
    if (*count >= HM2_TRAM_MAX_REGIONS) {
        HM2_ERR(hm2, "too many TRAM regions (max %d)\n", HM2_TRAM_MAX_REGIONS);
        return -ENOMEM;
    }
    list[*count].addr = (uint16_t)addr;
    list[*count].size = (uint16_t)size;
    list[*count].buffer = buffer;
    (*count)++;
    return 0;
}

/* Lazily create the region lists of a board. */
static int ensure_tram(hm2_board_t *hm2)
{
    if (hm2->tram)
        return 0;
    hm2->tram = calloc(1, sizeof(*hm2->tram));
    if (!hm2->tram) {
        HM2_ERR(hm2, "out of memory for the TRAM tables\n");
        return -ENOMEM;
    }
    return 0;
}

/* A block read every cycle (read-request order = registration order). */
int hm2_register_tram_read_region(hm2_board_t *hm2, uint32_t addr, int size, uint32_t **buffer)
{
    int r = ensure_tram(hm2);
    if (r < 0)
        return r;
    return add_region(hm2, hm2->tram->read, &hm2->tram->num_read, addr, size, buffer);
}

/* A block written every cycle. */
int hm2_register_tram_write_region(hm2_board_t *hm2, uint32_t addr, int size, uint32_t **buffer)
{
    int r = ensure_tram(hm2);
    if (r < 0)
        return r;
    return add_region(hm2, hm2->tram->write, &hm2->tram->num_write, addr, size, buffer);
}

/* Give every region of a list its slice of one zeroed buffer. */
static int allocate_list(hm2_tram_region_t *list, int count, uint32_t **buf)
{
    size_t words = 0;
    for (int i = 0; i < count; i++)
        words += (list[i].size + 3) / 4;
    *buf = calloc(words ? words : 1, sizeof(uint32_t));
    if (!*buf)
        return -ENOMEM;
    size_t at = 0;
    for (int i = 0; i < count; i++) {
        *list[i].buffer = *buf + at;
        at += (list[i].size + 3) / 4;
    }
    return 0;
}

/* (Re)allocate the read and write buffers once every module has registered its regions. */
int hm2_allocate_tram_regions(hm2_board_t *hm2)
{
    int r = ensure_tram(hm2);
    if (r == 0) {
        free(hm2->tram->read_buf);
        free(hm2->tram->write_buf);
        hm2->tram->read_buf = hm2->tram->write_buf = NULL;
    }
    if (r == 0)
        r = allocate_list(hm2->tram->read, hm2->tram->num_read, &hm2->tram->read_buf);
    if (r == 0)
        r = allocate_list(hm2->tram->write, hm2->tram->num_write, &hm2->tram->write_buf);
    if (r < 0)
        HM2_ERR(hm2, "out of memory for the TRAM buffers\n");
    return r;
}

/* Queue every read region (read-request) and send them when the driver queues. */
int hm2_tram_queue_reads(hm2_board_t *hm2)
{
    hm2_tram_t *t = hm2->tram;
    for (int i = 0; i < t->num_read; i++) {
        int r = hm2_queue_read(hm2, t->read[i].addr, *t->read[i].buffer, t->read[i].size);
        if (r < 0) {
            HM2_ERR(hm2, "TRAM read error! (addr=0x%04x, size=%d, iter=%u)\n",
                    t->read[i].addr, t->read[i].size, hm2->read_iter);
            return r;
        }
    }
    if (hm2->llio->ops->send_queued_reads) {
        int r = hm2->llio->ops->send_queued_reads(hm2->llio);
        if (r < 0) {
            HM2_ERR(hm2, "error queuing read! iter=%u)\n", hm2->read_iter);
            return r;
        }
    }
    return 0;
}

/* Wait for the queued reads; -EAGAIN = lost this cycle, other errors are hard. */
int hm2_tram_receive_reads(hm2_board_t *hm2)
{
    if (!hm2->llio->ops->receive_queued_reads)
        return 0;
    return hm2->llio->ops->receive_queued_reads(hm2->llio);
}

/* Queue every write region (the write funct adds config writes after them). */
int hm2_tram_queue_writes(hm2_board_t *hm2)
{
    hm2_tram_t *t = hm2->tram;
    for (int i = 0; i < t->num_write; i++) {
        int r = hm2_queue_write(hm2, t->write[i].addr, *t->write[i].buffer, t->write[i].size);
        if (r < 0) {
            HM2_ERR(hm2, "TRAM write error! (addr=0x%04x, size=%d, iter=%u)\n",
                    t->write[i].addr, t->write[i].size, hm2->write_iter);
            return r;
        }
    }
    return 0;
}

/* Send what the write funct queued. */
int hm2_tram_send_writes(hm2_board_t *hm2)
{
    if (!hm2->llio->ops->send_queued_writes)
        return 0;
    int r = hm2->llio->ops->send_queued_writes(hm2->llio);
    if (r < 0 && r != -EAGAIN)
        HM2_ERR(hm2, "error finishing write! iter=%u)\n", hm2->write_iter);
    return r;
}

/* Free the tables and buffers. */
void hm2_tram_free(hm2_board_t *hm2)
{
    if (!hm2->tram)
        return;
    free(hm2->tram->read_buf);
    free(hm2->tram->write_buf);
    free(hm2->tram);
    hm2->tram = NULL;
}
