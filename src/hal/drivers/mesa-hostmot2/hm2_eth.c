/* hm2_eth.c: the hm2_eth module: Mesa Ethernet boards (LBP16 over UDP) registered with hostmot2. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "hm2_eth.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Driver for Mesa Ethernet boards running HostMot2 (LBP16 over UDP)");

static char *board_ip[HM2_ETH_MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(board_ip, HM2_ETH_MAX_BOARDS, "IP address of each board");
static char *board_rtnet[HM2_ETH_MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(board_rtnet, HM2_ETH_MAX_BOARDS, "network stack of each board: posix (default) or evl");
static char *config[HM2_ETH_MAX_BOARDS];
RTAPI_MP_ARRAY_STRING(config, HM2_ETH_MAX_BOARDS, "hostmot2 config string of each board");
int debug = 0;
RTAPI_MP_INT(debug, "print every packet");
static char *firewall = "auto";
RTAPI_MP_STRING(firewall, "firewall backend: auto, iptables, nft or none");

static int comp_id;
static hm2_eth_board_t *boards;
static int num_boards;
static bool firewall_on;

/* Every board_rtnet entry must be posix (or unset). */
static int check_rtnet(void)
{
    for (int i = 0; i < HM2_ETH_MAX_BOARDS; i++) {
        const char *r = board_rtnet[i];
        if (!r || !*r || !strcmp(r, "posix"))
            continue;
        if (!strcmp(r, "evl"))
            rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: board_rtnet = evl not available, OpenEMC was "
                            "built without Xenomai EVL support\n");
        else
            rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: board_rtnet = %s undefined\n", r);
        return -EINVAL;
    }
    return 0;
}

/* Steps 1-6 of one board: socket, warning, MAC, ARP, firewall rule. */
static int init_board(hm2_eth_board_t *b)
{
    uint8_t raw[6], mac[6];
    rtapi_print("hm2_eth: %s: INFO: init board (POSIX)\n", b->ip);
    int r = hm2_eth_open(b);
    if (r < 0)
        return r;
    if (!firewall_on)
        rtapi_print("hm2_eth: WARNING: Unable to restrict other access to the hm2-eth device.\n"
                    "This means that other software using the same network interface can violate\n"
                    "realtime guarantees.  See hm2_eth(9) for more information.\n");
    r = hm2_eth_read_space(b, LBP16_SPACE_ETH_EEPROM, 2, LBP16_ADDR_MAC, raw, 3);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: Could not retrieve hardware address (MAC) of %s: %s\n",
                        b->ip, strerror(-r));
        return r;
    }
    for (int i = 0; i < 6; i++)
        mac[i] = raw[5 - i];
    rtapi_print("hm2_eth: %s: INFO: Hardware address (MAC): %02x:%02x:%02x:%02x:%02x:%02x\n", b->ip,
                mac[0], mac[1], mac[2], mac[3], mac[4], mac[5]);
    hm2_eth_pin_arp(b, mac);
    if (firewall_on)
        hm2_eth_firewall_add(b);
    return 0;
}

/* Unknown boards: geometry from the IDROM, connectors named "??". */
static int describe_unknown(hm2_eth_board_t *b, const char *name)
{
    uint32_t offset, words[2];
    rtapi_print("hm2_eth: Unrecognized ethernet board found: %.16s -- port names will be wrong\n", name);
    int r = hm2_eth_read_space(b, LBP16_SPACE_HOSTMOT2, 4, 0x010C, &offset, 1);
    if (r == 0)
        r = hm2_eth_read_space(b, LBP16_SPACE_HOSTMOT2, 4, (uint16_t)((offset & 0xFFFF) + 0x1C), &words[0], 1);
    if (r == 0)
        r = hm2_eth_read_space(b, LBP16_SPACE_HOSTMOT2, 4, (uint16_t)((offset & 0xFFFF) + 0x24), &words[1], 1);
    if (r < 0)
        return r;
    b->llio.num_ioport_connectors = words[0] > HM2_LLIO_MAX_CONNECTORS ? HM2_LLIO_MAX_CONNECTORS : (int)words[0];
    b->llio.pins_per_connector = (int)words[1];
    for (int i = 0; i < HM2_LLIO_MAX_CONNECTORS; i++)
        b->llio.ioport_connector_name[i] = "??";
    b->llio.fpga_part_number = "??";
    b->llio.num_leds = 0;
    return 0;
}

/* The HAL board name ("7i92") and its index among this driver's boards of that name. */
static void name_board(hm2_eth_board_t *b, const char *hal_name)
{
    int idx = 0;
    char prefix[HAL_NAME_LEN + 1];
    rtapi_snprintf(prefix, sizeof(prefix), "hm2_%s.", hal_name);
    for (hm2_eth_board_t *o = boards; o < b; o++)
        if (strncmp(o->llio.name, prefix, strlen(prefix)) == 0)
            idx++;
    rtapi_snprintf(b->llio.name, sizeof(b->llio.name), "hm2_%s.%d", hal_name, idx);
}

/* Step 7: read the board name, describe the board, hand it to hostmot2. */
static int probe_board(hm2_eth_board_t *b, int i)
{
    char name[LBP16_BOARD_NAME_LEN + 1] = {0}, hal_name[8] = {0};
    int r = hm2_eth_read_space(b, LBP16_SPACE_BOARD_INFO, 2, 0, name, LBP16_BOARD_NAME_LEN / 2);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: %s: ERROR: could not read the board name: %s\n", b->ip, strerror(-r));
        return r;
    }
    const hm2_eth_board_desc_t *d = hm2_eth_find_board(name);
    if (d) {
        b->llio.num_ioport_connectors = d->connectors;
        for (int c = 0; c < d->connectors; c++)
            b->llio.ioport_connector_name[c] = d->connector_names[c];
        b->llio.pins_per_connector = d->pins_per_connector;
        b->llio.fpga_part_number = d->fpga;
        b->llio.num_leds = d->leds;
        rtapi_snprintf(hal_name, sizeof(hal_name), "%s", d->hal_name);
    } else if ((r = describe_unknown(b, name)) < 0) {
        return r;
    } else {
        for (int k = 0; k < 4 && name[k]; k++)
            hal_name[k] = (char)tolower((unsigned char)name[k]);
    }
    b->force_enqueue_allowed = strncmp(name, "litehm2", 7) == 0;
    rtapi_print("hm2_eth: discovered %.16s\n", name);
    name_board(b, hal_name);
    b->llio.comp_id = comp_id;
    b->llio.split_read = true;
    b->llio.ops = &hm2_eth_ops;
    b->llio.driver_data = b;
    r = hm2_register(&b->llio, config[i]);
    if (r < 0) {
        rtapi_print("hm2_eth: %s: board fails HM2 registration\n", b->ip);
        return r;
    }
    return hm2_eth_export_hal(b);
}

/* realtime-init funct: per-board network set-up in the thread (nothing to do for POSIX sockets). */
static void realtime_init(void *arg, long period)
{
    (void)arg; (void)period;
}

/* Release everything of the boards set up so far. */
static void teardown(void)
{
    for (int i = 0; i < num_boards; i++) {
        hm2_eth_board_t *b = &boards[i];
        hm2_unregister(&b->llio);
        if (b->sockfd >= 0)
            hm2_eth_send_bite(b);
        hm2_eth_unpin_arp(b);
        hm2_eth_close(b);
    }
    if (firewall_on)
        hm2_eth_firewall_cleanup();
    free(boards);
    boards = NULL;
    num_boards = 0;
}

/* Boards in board_ip order until the first empty entry. */
static int count_boards(void)
{
    int n = 0;
    while (n < HM2_ETH_MAX_BOARDS && board_ip[n] && board_ip[n][0])
        n++;
    return n;
}

/* Load: steps 1-6 for every board, then 7-8 for every board, then the funct. */
int rtapi_app_main(void)
{
    rtapi_print("hm2_eth: loading Mesa AnyIO HostMot2 ethernet driver version 0.2\n");
    int r = check_rtnet();
    if (r < 0)
        return -1;
    comp_id = hal_init("hm2_eth");
    if (comp_id < 0)
        return comp_id;
    int n = count_boards();
    boards = calloc(n ? n : 1, sizeof(*boards));
    if (!boards) {
        hal_exit(comp_id);
        return -ENOMEM;
    }
    if (n > 0)
        firewall_on = hm2_eth_firewall_probe(firewall ? firewall : "auto");
    for (num_boards = 0, r = 0; num_boards < n && r == 0; num_boards++) {
        boards[num_boards].sockfd = -1;
        boards[num_boards].ip = board_ip[num_boards];
        boards[num_boards].comp_id = comp_id;
        r = init_board(&boards[num_boards]);
    }
    for (int i = 0; i < n && r == 0; i++)
        r = probe_board(&boards[i], i);
    if (r == 0)
        r = hal_export_funct("hm2_eth.realtime-init", realtime_init, NULL, 0, 0, comp_id);
    if (r < 0) {
        teardown();
        hal_exit(comp_id);
        return r;
    }
    hal_ready(comp_id);
    return 0;
}

/* Unload: every board bites its watchdog (outputs safe), rules and sockets go. */
void rtapi_app_exit(void)
{
    rtapi_print("hm2_eth: in hm2_eth_reset\n");
    teardown();
    rtapi_print("hm2_eth: HostMot2 ethernet driver unloaded\n");
    hal_exit(comp_id);
}
