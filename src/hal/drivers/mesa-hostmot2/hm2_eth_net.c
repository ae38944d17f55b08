/* hm2_eth_net.c: hm2_eth's UDP socket, interface lookup, ARP pinning and the optional firewall rules. */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <ifaddrs.h>
#include <net/if_arp.h>
#include <poll.h>
#include <spawn.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "rtapi.h"
#include "hm2_eth.h"

extern char **environ;

enum { FW_NONE, FW_IPTABLES, FW_NFT };
static int firewall_kind = FW_NONE;
#define FW_CHAIN "hm2-eth-rules-output"

/* Interface holding our local address, for the firewall rules and ARP. */
static void find_interface(hm2_eth_board_t *b)
{
    struct ifaddrs *list, *i;
    b->ifname[0] = '\0';
    if (getifaddrs(&list) < 0)
        return;
    for (i = list; i; i = i->ifa_next) {
        if (!i->ifa_addr || i->ifa_addr->sa_family != AF_INET)
            continue;
        if (((struct sockaddr_in *)i->ifa_addr)->sin_addr.s_addr == b->local_addr.sin_addr.s_addr) {
            snprintf(b->ifname, sizeof(b->ifname), "%s", i->ifa_name);
            break;
        }
    }
    freeifaddrs(list);
}

/* UDP socket connected to board_ip:27181. */
int hm2_eth_open(hm2_eth_board_t *b)
{
    b->sockfd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (b->sockfd < 0) {
        int e = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: can't open socket: %s\n", strerror(e));
        return -e;
    }
    memset(&b->board_addr, 0, sizeof(b->board_addr));
    b->board_addr.sin_family = AF_INET;
    b->board_addr.sin_port = htons(LBP16_UDP_PORT);
    if (inet_pton(AF_INET, b->ip, &b->board_addr.sin_addr) != 1) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: board_ip '%s' is not an IPv4 address\n", b->ip);
        hm2_eth_close(b);
        return -EINVAL;
    }
    if (connect(b->sockfd, (struct sockaddr *)&b->board_addr, sizeof(b->board_addr)) < 0) {
        int e = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: can't connect: %s\n", strerror(e));
        hm2_eth_close(b);
        return -e;
    }
    socklen_t len = sizeof(b->local_addr);
    getsockname(b->sockfd, (struct sockaddr *)&b->local_addr, &len);
    find_interface(b);
    if (!b->ifname[0])
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: %s: failed to retrieve interface name for board\n", b->ip);
    return 0;
}

/* Close the socket (once). */
void hm2_eth_close(hm2_eth_board_t *b)
{
    if (b->sockfd >= 0)
        close(b->sockfd);
    b->sockfd = -1;
}

/* debug=1: every datagram in hex on stdout. */
static void dump_packet(const hm2_eth_board_t *b, const char *what, const uint8_t *data, int len)
{
    char line[3 * 32 + 1];
    rtapi_print("hm2_eth: %s: %s %d bytes\n", b->ip, what, len);
    for (int at = 0; at < len; at += 32) {
        int n = len - at < 32 ? len - at : 32;
        for (int i = 0; i < n; i++)
            snprintf(line + 3 * i, 4, " %02x", data[at + i]);
        rtapi_print("hm2_eth:   %04x:%s\n", at, line);
    }
}

/* One datagram; 0 or -errno (reported by the caller). */
int hm2_eth_send(hm2_eth_board_t *b, const void *data, int len)
{
    if (debug)
        dump_packet(b, "sent", data, len);
    ssize_t n = send(b->sockfd, data, len, 0);
    if (n < 0)
        return -errno;
    return n == len ? 0 : -EIO;
}

/* Monotonic time in ns. */
static long long now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* Wait for one datagram until the deadline: its length, -EAGAIN at the deadline, or -errno. */
int hm2_eth_recv_until(hm2_eth_board_t *b, void *buf, int cap, long long deadline_ns)
{
    for (;;) {
        long long left = deadline_ns - now_ns();
        if (left <= 0)
            return -EAGAIN;
        struct pollfd pfd = {b->sockfd, POLLIN, 0};
        struct timespec ts = {left / 1000000000LL, left % 1000000000LL};
        int r = ppoll(&pfd, 1, &ts, NULL);
        if (r < 0 && errno != EINTR)
            return -errno;
        if (r <= 0)
            continue;
        ssize_t n = recv(b->sockfd, buf, cap, MSG_DONTWAIT);
        if (n >= 0 && debug)
            dump_packet(b, "received", buf, (int)n);
        if (n >= 0)
            return (int)n;
        if (errno != EAGAIN && errno != EINTR)
            return -errno;
    }
}

/* Pin the board's ARP entry (needs CAP_NET_ADMIN); dynamic ARP otherwise. */
void hm2_eth_pin_arp(hm2_eth_board_t *b, const uint8_t mac[6])
{
    struct arpreq req;
    memset(&req, 0, sizeof(req));
    memcpy(&req.arp_pa, &b->board_addr, sizeof(b->board_addr));
    req.arp_ha.sa_family = ARPHRD_ETHER;
    memcpy(req.arp_ha.sa_data, mac, 6);
    req.arp_flags = ATF_PERM | ATF_COM;
    snprintf(req.arp_dev, sizeof(req.arp_dev), "%s", b->ifname);
    if (ioctl(b->sockfd, SIOCSARP, &req) < 0) {
        rtapi_print("hm2_eth: WARNING: ioctl SIOCSARP failed: %s; continuing with dynamic ARP.  "
                    "Give rtapi_app CAP_NET_ADMIN (setcap cap_net_admin+ep) or run it as root to pin "
                    "the board's ARP entry and avoid occasional transmit latency.\n", strerror(errno));
        return;
    }
    b->arp_pinned = true;
}

/* Remove a pinned ARP entry at unload. */
void hm2_eth_unpin_arp(hm2_eth_board_t *b)
{
    struct arpreq req;
    if (!b->arp_pinned)
        return;
    memset(&req, 0, sizeof(req));
    memcpy(&req.arp_pa, &b->board_addr, sizeof(b->board_addr));
    snprintf(req.arp_dev, sizeof(req.arp_dev), "%s", b->ifname);
    ioctl(b->sockfd, SIOCDARP, &req);
    b->arp_pinned = false;
}

/* Run a firewall command quietly; true when it exits 0. */
static bool run_quiet(const char *const argv[])
{
    posix_spawn_file_actions_t fa;
    pid_t pid;
    int status = -1;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    int r = posix_spawnp(&pid, argv[0], &fa, NULL, (char *const *)argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (r != 0)
        return false;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* The rules of one board: its own traffic allowed, everything else on its interface refused. */
static void iptables_board(hm2_eth_board_t *b)
{
    char dst[32], src[32], sport[16];
    inet_ntop(AF_INET, &b->board_addr.sin_addr, dst, sizeof(dst));
    inet_ntop(AF_INET, &b->local_addr.sin_addr, src, sizeof(src));
    snprintf(sport, sizeof(sport), "%d", ntohs(b->local_addr.sin_port));
    const char *accept[] = {"iptables", "-A", FW_CHAIN, "-p", "udp", "-m", "udp", "-d", dst, "--dport",
                            "27181", "-s", src, "--sport", sport, "-j", "ACCEPT", NULL};
    run_quiet(accept);
    if (!b->ifname[0] || strcmp(b->ifname, "lo") == 0)
        return;
    const char *icmp[] = {"iptables", "-A", FW_CHAIN, "-o", b->ifname, "-p", "icmp", "-j", "DROP", NULL};
    const char *rest[] = {"iptables", "-A", FW_CHAIN, "-o", b->ifname, "-j", "REJECT", "--reject-with",
                          "icmp-admin-prohibited", NULL};
    const char *v6[] = {"ip6tables", "-A", FW_CHAIN, "-o", b->ifname, "-j", "DROP", NULL};
    run_quiet(icmp);
    run_quiet(rest);
    run_quiet(v6);
}

/* nft equivalents of iptables_board. */
static void nft_board(hm2_eth_board_t *b)
{
    char rule[512], dst[32], src[32];
    inet_ntop(AF_INET, &b->board_addr.sin_addr, dst, sizeof(dst));
    inet_ntop(AF_INET, &b->local_addr.sin_addr, src, sizeof(src));
    snprintf(rule, sizeof(rule), "add rule inet hm2_eth output ip daddr %s udp dport 27181 ip saddr %s "
             "udp sport %d accept", dst, src, ntohs(b->local_addr.sin_port));
    const char *accept[] = {"nft", rule, NULL};
    run_quiet(accept);
    if (!b->ifname[0] || strcmp(b->ifname, "lo") == 0)
        return;
    snprintf(rule, sizeof(rule), "add rule inet hm2_eth output oifname %s ip protocol icmp drop; "
             "add rule inet hm2_eth output oifname %s meta nfproto ipv4 reject with icmp type "
             "admin-prohibited; add rule inet hm2_eth output oifname %s meta nfproto ipv6 drop",
             b->ifname, b->ifname, b->ifname);
    const char *rest[] = {"nft", rule, NULL};
    run_quiet(rest);
}

/* Create (or flush) the chain / table and jump to it from OUTPUT. */
static void firewall_base(void)
{
    if (firewall_kind == FW_IPTABLES) {
        const char *tools[] = {"iptables", "ip6tables"};
        for (int t = 0; t < 2; t++) {
            const char *mk[] = {tools[t], "-N", FW_CHAIN, NULL};
            const char *flush[] = {tools[t], "-F", FW_CHAIN, NULL};
            const char *check[] = {tools[t], "-C", "OUTPUT", "-j", FW_CHAIN, NULL};
            const char *jump[] = {tools[t], "-I", "OUTPUT", "1", "-j", FW_CHAIN, NULL};
            run_quiet(mk);
            run_quiet(flush);
            if (!run_quiet(check))
                run_quiet(jump);
        }
    } else if (firewall_kind == FW_NFT) {
        const char *del[] = {"nft", "delete table inet hm2_eth", NULL};
        const char *mk[] = {"nft", "add table inet hm2_eth; add chain inet hm2_eth output "
                            "{ type filter hook output priority 0; policy accept; }", NULL};
        run_quiet(del);
        run_quiet(mk);
    }
}

/* Probe the backend (once, before the boards); true when rules can be added. */
bool hm2_eth_firewall_probe(const char *backend)
{
    const char *ipt[] = {"iptables", "-n", "-L", "INPUT", NULL};
    const char *nft[] = {"nft", "list", "tables", NULL};
    bool want_ipt = !strcmp(backend, "auto") || !strcmp(backend, "iptables");
    bool want_nft = !strcmp(backend, "auto") || !strcmp(backend, "nft") || !strcmp(backend, "nftables");
    firewall_kind = FW_NONE;
    if (!strcmp(backend, "none"))
        return false;
    if (!want_ipt && !want_nft) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: ERROR: unknown firewall backend '%s'; expected auto, "
                        "iptables, nft, or none.\n", backend);
        return false;
    }
    if (want_ipt && run_quiet(ipt))
        firewall_kind = FW_IPTABLES;
    else if (want_nft && run_quiet(nft))
        firewall_kind = FW_NFT;
    if (firewall_kind == FW_NONE) {
        rtapi_print("hm2_eth: firewall not available (missing CAP_NET_ADMIN or backend binary?); "
                    "automatic firewall setup skipped.  See hm2_eth(9) NOTES for the manual rule recipe.\n");
        return false;
    }
    firewall_base();
    return true;
}

/* Add one board's rules (after its socket is connected). */
void hm2_eth_firewall_add(hm2_eth_board_t *b)
{
    if (firewall_kind == FW_IPTABLES)
        iptables_board(b);
    else if (firewall_kind == FW_NFT)
        nft_board(b);
}

/* Remove the rules added at load. */
void hm2_eth_firewall_cleanup(void)
{
    if (firewall_kind == FW_IPTABLES) {
        const char *tools[] = {"iptables", "ip6tables"};
        for (int t = 0; t < 2; t++) {
            const char *flush[] = {tools[t], "-F", FW_CHAIN, NULL};
            const char *unjump[] = {tools[t], "-D", "OUTPUT", "-j", FW_CHAIN, NULL};
            const char *del[] = {tools[t], "-X", FW_CHAIN, NULL};
            run_quiet(flush);
            run_quiet(unjump);
            run_quiet(del);
        }
    } else if (firewall_kind == FW_NFT) {
        const char *del[] = {"nft", "delete table inet hm2_eth", NULL};
        run_quiet(del);
    }
    firewall_kind = FW_NONE;
}
