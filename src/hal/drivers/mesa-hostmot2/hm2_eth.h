/* hm2_eth.h: state of one Ethernet board of hm2_eth (socket, LBP16 queues, packet-error pins). */
#ifndef HM2_ETH_H
#define HM2_ETH_H

#include <netinet/in.h>
#include <net/if.h>
#include "hal.h"
#include "hostmot2.h"
#include "lbp16.h"

#define HM2_ETH_MAX_BOARDS 4
#define HM2_ETH_MAX_QUEUED_READS 64
#define HM2_ETH_LOAD_TIMEOUT_NS 200000000LL
#define HM2_ETH_MIN_READ_TIMEOUT_NS 100000LL
#define HM2_ETH_DEFAULT_READ_TIMEOUT 80

/* A board description from its name (the table in hm2_eth_boards.c). */
typedef struct {
    const char *match;          /* name prefix to compare */
    int match_len;              /* bytes compared (NUL padding included) */
    const char *hal_name;       /* e.g. "7i92" */
    int connectors;
    const char *connector_names[4];
    int pins_per_connector;
    const char *fpga;
    int leds;
    bool force_enqueue;         /* litehm2: all force-writes in one datagram */
} hm2_eth_board_desc_t;

/* The board's extra HAL objects. */
typedef struct {
    hal_bit_t *packet_error, *packet_error_exceeded;
    hal_s32_t *packet_error_level;
    hal_u32_t *packet_error_total;
    hal_s32_t packet_error_limit, packet_error_increment, packet_error_decrement;
    hal_s32_t packet_read_timeout;
} hm2_eth_hal_t;

/* A queued read: where its reply bytes go. */
typedef struct {
    void *buffer;
    int size;
} hm2_eth_read_t;

typedef struct {
    hm2_llio_t llio;
    const char *ip;
    int sockfd;
    struct sockaddr_in board_addr, local_addr;
    char ifname[IF_NAMESIZE];
    bool arp_pinned;
    bool force_enqueue, force_enqueue_allowed;
    bool warned_rt_read;
    bool skip_write_seq_check;      /* after io_error recovery: writes were knowingly not sent */

    lbp16_packet_t read_packet, write_packet;
    hm2_eth_read_t queued_reads[HM2_ETH_MAX_QUEUED_READS];
    int num_queued_reads;
    uint32_t read_seq, write_seq;
    long long read_sent_ns;
    uint16_t rx_udp_count;
    uint8_t seq_echo[8];

    hm2_eth_hal_t *hal;
    int comp_id;
} hm2_eth_board_t;

/* The debug module parameter: print every datagram. */
extern int debug;

/* Board description for a 16-byte name; NULL = unknown board. */
const hm2_eth_board_desc_t *hm2_eth_find_board(const char name[LBP16_BOARD_NAME_LEN]);

/* ---- network (hm2_eth_net.c) ---- */
int hm2_eth_open(hm2_eth_board_t *b);
void hm2_eth_close(hm2_eth_board_t *b);
int hm2_eth_send(hm2_eth_board_t *b, const void *data, int len);
int hm2_eth_recv_until(hm2_eth_board_t *b, void *buf, int cap, long long deadline_ns);
void hm2_eth_pin_arp(hm2_eth_board_t *b, const uint8_t mac[6]);
void hm2_eth_unpin_arp(hm2_eth_board_t *b);
bool hm2_eth_firewall_probe(const char *backend);
void hm2_eth_firewall_add(hm2_eth_board_t *b);
void hm2_eth_firewall_cleanup(void);

/* ---- LBP16 transfers (hm2_eth_io.c) ---- */
extern const hm2_llio_ops_t hm2_eth_ops;
int hm2_eth_read_space(hm2_eth_board_t *b, int space, int elem_bytes, uint16_t addr, void *buf,
                       int count);
int hm2_eth_export_hal(hm2_eth_board_t *b);
void hm2_eth_send_bite(hm2_eth_board_t *b);

#endif
