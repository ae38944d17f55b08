/* hm2_eth_io.c: hm2_eth's llio ops: LBP16 reads and writes, the per-cycle datagrams, packet errors. */
#include <string.h>
#include <time.h>
#include "rtapi.h"
#include "rtapi_errno.h"
#include "hm2_eth.h"

#define BITE_ADDR 0x0C00
#define WORD_BYTES 4
#define SEQ_ECHO_BYTES 8
#define RX_COUNT_BYTES 2

/* The llio is the first member of the board. */
static hm2_eth_board_t *board_of(hm2_llio_t *llio)
{
    return (hm2_eth_board_t *)llio;
}

/* Monotonic time in ns. */
static long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Called from a HAL thread? Then transfers go with the cycle's datagrams. */
static bool in_realtime(void)
{
    return rtapi_task_self() >= 0;
}

/* Read timeout: percent of the thread period below 100, else ns; at least 100 us. */
static long long read_timeout_ns(hm2_eth_board_t *b)
{
    long period = b->llio.period_ns;
    if (period <= 0)
        return HM2_ETH_LOAD_TIMEOUT_NS;
    long long t = b->hal ? b->hal->packet_read_timeout : HM2_ETH_DEFAULT_READ_TIMEOUT;
    if (t <= 0)
        t = HM2_ETH_DEFAULT_READ_TIMEOUT;
    if (t < 100)
        t = period * t / 100;
    return t < HM2_ETH_MIN_READ_TIMEOUT_NS ? HM2_ETH_MIN_READ_TIMEOUT_NS : t;
}

/* Blocking read of count elements of one space, one datagram per 127 elements. */
int hm2_eth_read_space(hm2_eth_board_t *b, int space, int elem_bytes, uint16_t addr, void *buf,
                       int count)
{
    uint8_t reply[LBP16_MAX_PACKET];
    lbp16_packet_t p;
    long long timeout = in_realtime() ? read_timeout_ns(b) : HM2_ETH_LOAD_TIMEOUT_NS;
    for (int done = 0; done < count;) {
        int n = count - done > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : count - done;
        lbp16_reset(&p);
        lbp16_add_read(&p, space, elem_bytes, (uint16_t)(addr + done * elem_bytes), n, true);
        int r = hm2_eth_send(b, p.data, p.len);
        long long deadline = now_ns() + timeout;
        while (r == 0) {
            r = hm2_eth_recv_until(b, reply, sizeof(reply), deadline);
            if (r == p.reply_len)
                break;
            r = r < 0 ? r : 0;
        }
        if (r < 0)
            return r;
        memcpy((uint8_t *)buf + done * elem_bytes, reply, p.reply_len);
        done += n;
    }
    return 0;
}

/* Direct register read (load time); from a HAL thread it costs an extra round trip. */
static int eth_read(hm2_llio_t *llio, uint32_t addr, void *buf, int size)
{
    hm2_eth_board_t *b = board_of(llio);
    if (in_realtime() && !b->warned_rt_read) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: used llio->read in realtime task (addr=0x%04x)\n", addr);
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: This causes additional network packets which hurts performance\n");
        b->warned_rt_read = true;
    }
    int r = hm2_eth_read_space(b, LBP16_SPACE_HOSTMOT2, WORD_BYTES, (uint16_t)addr, buf, size / WORD_BYTES);
    if (r < 0 && !in_realtime())
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: %s: ERROR: reading 0x%04x (%d bytes): %s\n", b->ip,
                        addr, size, strerror(-r));
    return r;
}

/* Queue a write into the cycle's write datagram. */
static int eth_queue_write(hm2_llio_t *llio, uint32_t addr, const void *buf, int size)
{
    hm2_eth_board_t *b = board_of(llio);
    int words = size / WORD_BYTES;
    for (int done = 0; done < words;) {
        int n = words - done > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : words - done;
        if (lbp16_add_write(&b->write_packet, LBP16_SPACE_HOSTMOT2, WORD_BYTES,
                            (uint16_t)(addr + done * WORD_BYTES),
                            (const uint8_t *)buf + done * WORD_BYTES, n, true) < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: enqueue_write: buffer full\n");
            return -ENOSPC;
        }
        done += n;
    }
    return 0;
}

/* Direct write (unacknowledged datagram); queued when called from a HAL thread. */
static int eth_write(hm2_llio_t *llio, uint32_t addr, const void *buf, int size)
{
    hm2_eth_board_t *b = board_of(llio);
    if (in_realtime() || b->force_enqueue)
        return eth_queue_write(llio, addr, buf, size);
    lbp16_packet_t p;
    int words = size / WORD_BYTES;
    for (int done = 0; done < words;) {
        int n = words - done > LBP16_MAX_COUNT ? LBP16_MAX_COUNT : words - done;
        lbp16_reset(&p);
        lbp16_add_write(&p, LBP16_SPACE_HOSTMOT2, WORD_BYTES, (uint16_t)(addr + done * WORD_BYTES),
                        (const uint8_t *)buf + done * WORD_BYTES, n, true);
        int r = hm2_eth_send(b, p.data, p.len);
        if (r < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: sending packet: %s\n", strerror(-r));
            return r;
        }
        done += n;
    }
    return 0;
}

/* Queue a read into the cycle's read datagram. */
static int eth_queue_read(hm2_llio_t *llio, uint32_t addr, void *buf, int size)
{
    hm2_eth_board_t *b = board_of(llio);
    if (b->num_queued_reads >= HM2_ETH_MAX_QUEUED_READS || size / WORD_BYTES > LBP16_MAX_COUNT ||
        lbp16_add_read(&b->read_packet, LBP16_SPACE_HOSTMOT2, WORD_BYTES, (uint16_t)addr,
                       size / WORD_BYTES, true) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: enqueue_read: buffer full\n");
        return -ENOSPC;
    }
    b->queued_reads[b->num_queued_reads].buffer = buf;
    b->queued_reads[b->num_queued_reads].size = size;
    b->num_queued_reads++;
    return 0;
}

/* Forget the queued reads (after a reply or an error). */
static void drop_reads(hm2_eth_board_t *b)
{
    lbp16_reset(&b->read_packet);
    b->num_queued_reads = 0;
}

/* A lost or bad exchange: raise the level; at the limit the board is in io_error. */
static int record_error(hm2_eth_board_t *b)
{
    hm2_eth_hal_t *h = b->hal;
    drop_reads(b);
    if (!h)
        return -EIO;
    *h->packet_error = 1;
    (*h->packet_error_total)++;
    int inc = h->packet_error_increment < 1 ? 1 : h->packet_error_increment;
    *h->packet_error_level += inc;
    if (*h->packet_error_level >= h->packet_error_limit) {
        *h->packet_error_level = h->packet_error_limit;
        *h->packet_error_exceeded = 1;
        *b->llio.io_error = 1;
        return -EIO;
    }
    return -EAGAIN;
}

/* A good exchange lowers the level. */
static void record_success(hm2_eth_board_t *b)
{
    hm2_eth_hal_t *h = b->hal;
    if (!h)
        return;
    int dec = h->packet_error_decrement < 1 ? 1 : h->packet_error_decrement;
    *h->packet_error_level = *h->packet_error_level > dec ? *h->packet_error_level - dec : 0;
    *h->packet_error = 0;
    *h->packet_error_exceeded = 0;
}

/* Append the status read and the read-sequence write/echo, then send the read datagram. */
static int eth_send_queued_reads(hm2_llio_t *llio)
{
    hm2_eth_board_t *b = board_of(llio);
    if (b->hal && *b->hal->packet_error_exceeded && !*llio->io_error) {
        *b->hal->packet_error_level = 0;
        *b->hal->packet_error_exceeded = 0;
        b->skip_write_seq_check = true;
    }
    uint32_t seq = ++b->read_seq;
    uint8_t le[4] = {seq & 0xFF, (seq >> 8) & 0xFF, (seq >> 16) & 0xFF, seq >> 24};
    if (lbp16_add_read(&b->read_packet, LBP16_SPACE_COMM_STATUS, 2, LBP16_ADDR_RX_UDP_COUNT, 1, false) < 0 ||
        lbp16_add_write(&b->read_packet, LBP16_SPACE_TIMER, 2, LBP16_ADDR_READ_SEQ, le, 2, true) < 0 ||
        lbp16_add_read(&b->read_packet, LBP16_SPACE_TIMER, 2, LBP16_ADDR_READ_SEQ, 4, true) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: send_queued_reads: buffer full, dropping all data\n");
        drop_reads(b);
        return -ENOSPC;
    }
    int r = hm2_eth_send(b, b->read_packet.data, b->read_packet.len);
    b->read_sent_ns = now_ns();
    if (r < 0)
        rtapi_print("hm2_eth: ERROR: sending packet: %s\n", strerror(-r));
    return 0;
}

/* Little-endian u32 of a reply. */
static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Hand the reply bytes to the queued reads; check the write-sequence echo. */
static int accept_reply(hm2_eth_board_t *b, const uint8_t *reply, int len)
{
    int at = 0;
    for (int i = 0; i < b->num_queued_reads; i++) {
        memcpy(b->queued_reads[i].buffer, reply + at, b->queued_reads[i].size);
        at += b->queued_reads[i].size;
    }
    b->rx_udp_count = (uint16_t)(reply[at] | reply[at + 1] << 8);
    memcpy(b->seq_echo, reply + len - SEQ_ECHO_BYTES, SEQ_ECHO_BYTES);
    drop_reads(b);
    bool skip = b->skip_write_seq_check;
    b->skip_write_seq_check = false;
    if (!skip && b->write_seq > 0 && le32(b->seq_echo + 4) != b->write_seq)
        return record_error(b);
    record_success(b);
    return 0;
}

/* Wait for the reply with our read sequence; stale or malformed replies are skipped. */
static int eth_receive_queued_reads(hm2_llio_t *llio)
{
    hm2_eth_board_t *b = board_of(llio);
    uint8_t reply[LBP16_MAX_PACKET];
    int expected = b->read_packet.reply_len;
    long long timeout = read_timeout_ns(b), deadline = b->read_sent_ns + timeout;
    for (;;) {
        int n = hm2_eth_recv_until(b, reply, sizeof(reply), deadline);
        if (n < 0) {
            rtapi_print("hm2_eth: receive_queued_reads: error (%s) after %lldns timeout=%lldns\n",
                        strerror(-n), now_ns() - b->read_sent_ns, timeout);
            return record_error(b);
        }
        if (n != expected || le32(reply + n - SEQ_ECHO_BYTES) != b->read_seq)
            continue;
        return accept_reply(b, reply, n);
    }
}

/* Append the write sequence number and send the cycle's write datagram. */
static int eth_send_queued_writes(hm2_llio_t *llio)
{
    hm2_eth_board_t *b = board_of(llio);
    uint32_t seq = b->write_seq + 1;
    uint8_t le[4] = {seq & 0xFF, (seq >> 8) & 0xFF, (seq >> 16) & 0xFF, seq >> 24};
    if (lbp16_add_write(&b->write_packet, LBP16_SPACE_TIMER, 2, LBP16_ADDR_WRITE_SEQ, le, 2, true) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: send_queued_writes: buffer full, dropping all data\n");
        lbp16_reset(&b->write_packet);
        return -ENOSPC;
    }
    b->write_seq = seq;
    int r = hm2_eth_send(b, b->write_packet.data, b->write_packet.len);
    lbp16_reset(&b->write_packet);
    if (r < 0) {
        rtapi_print("hm2_eth: ERROR: sending packet: %s\n", strerror(-r));
        return record_error(b);
    }
    return 0;
}

/* litehm2 boards put every force-write into one datagram. */
static void eth_set_force_enqueue(hm2_llio_t *llio, bool on)
{
    hm2_eth_board_t *b = board_of(llio);
    b->force_enqueue = on && b->force_enqueue_allowed;
}

/* Board reset: a watchdog of one clock (every output goes safe at once). */
static int eth_reset(hm2_llio_t *llio)
{
    hm2_eth_send_bite(board_of(llio));
    return 0;
}

/* The bite datagram: 0xC281 at 0x0C00 with data 1. */
void hm2_eth_send_bite(hm2_eth_board_t *b)
{
    lbp16_packet_t p;
    uint32_t one = 1;
    lbp16_reset(&p);
    lbp16_add_write(&p, LBP16_SPACE_HOSTMOT2, WORD_BYTES, BITE_ADDR, &one, 1, true);
    hm2_eth_send(b, p.data, p.len);
}

const hm2_llio_ops_t hm2_eth_ops = {
    .version = HM2_LLIO_OPS_VERSION,
    .read = eth_read,
    .write = eth_write,
    .queue_read = eth_queue_read,
    .send_queued_reads = eth_send_queued_reads,
    .receive_queued_reads = eth_receive_queued_reads,
    .queue_write = eth_queue_write,
    .send_queued_writes = eth_send_queued_writes,
    .set_force_enqueue = eth_set_force_enqueue,
    .reset = eth_reset,
};
