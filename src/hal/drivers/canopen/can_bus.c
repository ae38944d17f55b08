/* can_bus.c: SocketCAN raw sockets for the cia402 driver and its simulated drive: kernel-side
   filtering, non-blocking recvmmsg/sendmmsg so a cycle costs one call each way. */
#define _GNU_SOURCE     /* recvmmsg, sendmmsg */
#include <errno.h>
#include <net/if.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <sys/ioctl.h>
#include <linux/can/raw.h>
#include "can_bus.h"

#define CAN_BUS_MAX_FILTERS 1024

/* Install one filter per COB-ID (standard frames only, remote requests included). */
static int set_filters(can_bus_t *bus, const uint16_t *ids, int id_count)
{
    struct can_filter filters[CAN_BUS_MAX_FILTERS];
    int n = id_count < CAN_BUS_MAX_FILTERS ? id_count : CAN_BUS_MAX_FILTERS;
    for (int i = 0; i < n; i++) {
        filters[i].can_id = ids[i];
        filters[i].can_mask = CAN_SFF_MASK | CAN_EFF_FLAG;
    }
    if (setsockopt(bus->fd, SOL_CAN_RAW, CAN_RAW_FILTER, filters, sizeof(filters[0]) * n) != 0)
        return -errno;
    return 0;
}

/* Check that the interface exists and is up; 0 or a negative errno with the reason. */
static int check_interface(can_bus_t *bus, struct ifreq *ifr, char *why, int why_len)
{
    memset(ifr, 0, sizeof(*ifr));
    snprintf(ifr->ifr_name, sizeof(ifr->ifr_name), "%s", bus->name);
    if (ioctl(bus->fd, SIOCGIFINDEX, ifr) != 0) {
        int e = errno;
        snprintf(why, why_len, "CAN interface %s not found (%s)", bus->name, strerror(e));
        return -e;
    }
    if (ioctl(bus->fd, SIOCGIFFLAGS, ifr) != 0 || !(ifr->ifr_flags & IFF_UP)) {
        snprintf(why, why_len, "CAN interface %s is down (ip link set %s up)", bus->name, bus->name);
        return -ENETDOWN;
    }
    return ioctl(bus->fd, SIOCGIFINDEX, ifr) == 0 ? 0 : -errno;
}

/* Open interface name for the given COB-IDs (none: every frame); 0 or a negative errno with a message in why. */
int can_bus_open(can_bus_t *bus, const char *name, const uint16_t *ids, int id_count, char *why, int why_len)
{
    struct sockaddr_can addr = { .can_family = AF_CAN };
    struct ifreq ifr;
    int r;
    memset(bus, 0, sizeof(*bus));
    snprintf(bus->name, sizeof(bus->name), "%s", name);
    bus->fd = socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (bus->fd < 0) {
        r = -errno;
        snprintf(why, why_len, "no SocketCAN raw socket for %s (%s)", name, strerror(-r));
        return r;
    }
    r = check_interface(bus, &ifr, why, why_len);
    if (r == 0 && id_count > 0) {
        r = set_filters(bus, ids, id_count);
        if (r != 0)
            snprintf(why, why_len, "cannot set the receive filters on %s (%s)", name, strerror(-r));
    }
    addr.can_ifindex = ifr.ifr_ifindex;
    if (r == 0 && bind(bus->fd, (struct sockaddr *)&addr, sizeof(addr)) != 0) {
        r = -errno;
        snprintf(why, why_len, "cannot bind to %s (%s)", name, strerror(-r));
    }
    if (r != 0)
        can_bus_close(bus);
    return r;
}

/* Read up to max pending frames without waiting into frames[] (*valid of them are classic standard
   frames); returns how many the socket gave (max: call again) or a negative errno. */
int can_bus_receive(can_bus_t *bus, co_frame_t *frames, int max, int *valid)
{
    struct can_frame raw[CAN_BUS_BATCH];
    struct iovec iov[CAN_BUS_BATCH];
    struct mmsghdr msgs[CAN_BUS_BATCH];
    int n = max < CAN_BUS_BATCH ? max : CAN_BUS_BATCH, got, k = 0;
    *valid = 0;
    for (int i = 0; i < n; i++) {
        iov[i] = (struct iovec){ .iov_base = &raw[i], .iov_len = sizeof(raw[i]) };
        msgs[i] = (struct mmsghdr){ .msg_hdr = { .msg_iov = &iov[i], .msg_iovlen = 1 } };
    }
    got = recvmmsg(bus->fd, msgs, n, MSG_DONTWAIT, NULL);
    if (got < 0) {
        if (errno == EAGAIN || errno == EWOULDBLOCK)
            return 0;
        bus->last_errno = errno;
        return -errno;
    }
    for (int i = 0; i < got; i++) {
        if (msgs[i].msg_len != sizeof(struct can_frame) || (raw[i].can_id & (CAN_EFF_FLAG | CAN_ERR_FLAG)))
            continue;
        frames[k].id = (uint16_t)(raw[i].can_id & CAN_SFF_MASK);
        frames[k].rtr = (raw[i].can_id & CAN_RTR_FLAG) != 0;
        frames[k].len = raw[i].can_dlc > 8 ? 8 : raw[i].can_dlc;
        memcpy(frames[k].data, raw[i].data, 8);
        k++;
    }
    *valid = k;
    return got;
}

/* Add a frame to this cycle's queue (frames past the batch size are counted as dropped). */
void can_bus_queue(can_bus_t *bus, const co_frame_t *f)
{
    struct can_frame *raw;
    if (bus->tx_count == CAN_BUS_BATCH) {
        bus->tx_dropped++;
        return;
    }
    raw = &bus->tx[bus->tx_count++];
    memset(raw, 0, sizeof(*raw));
    raw->can_id = f->id | (f->rtr ? CAN_RTR_FLAG : 0);
    raw->can_dlc = f->len;
    memcpy(raw->data, f->data, f->len);
}

/* Send the queued frames with one call, without waiting; 0 or a negative errno. */
int can_bus_flush(can_bus_t *bus)
{
    struct iovec iov[CAN_BUS_BATCH];
    struct mmsghdr msgs[CAN_BUS_BATCH];
    int n = bus->tx_count, sent;
    bus->tx_count = 0;
    if (n == 0)
        return 0;
    for (int i = 0; i < n; i++) {
        iov[i] = (struct iovec){ .iov_base = &bus->tx[i], .iov_len = sizeof(bus->tx[i]) };
        msgs[i] = (struct mmsghdr){ .msg_hdr = { .msg_iov = &iov[i], .msg_iovlen = 1 } };
    }
    sent = sendmmsg(bus->fd, msgs, n, MSG_DONTWAIT);
    if (sent == n)
        return 0;
    bus->tx_dropped += (uint32_t)(n - (sent > 0 ? sent : 0));
    if (sent < 0) {
        bus->last_errno = errno;
        return -errno;
    }
    return -EAGAIN;
}

/* Close the socket. */
void can_bus_close(can_bus_t *bus)
{
    if (bus->fd >= 0)
        close(bus->fd);
    bus->fd = -1;
}
