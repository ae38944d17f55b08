/* parport_io.c: find a parallel port, claim it through ppdev and reach its registers
   by ppdev ioctls or, where the address is given and the process may, by raw port I/O. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <sys/ioctl.h>
#include <linux/parport.h>
#include <linux/ppdev.h>
#include "rtapi.h"
#include "parport_bits.h"
#include "parport_io.h"
#if defined(__x86_64__) || defined(__i386__)
#include <sys/io.h>
#define PP_HAVE_PORT_IO 1
#endif

#define PP_PROC_FMT "/proc/sys/dev/parport/parport%d/base-addr"
#define PP_REGISTERS 3            /* data, status, control */
#define PP_ECR_OFFSET 2           /* extended control register at base_hi + 2 */
#define PP_ECR_EPP 0x94u          /* ECR mode 100 (EPP), error interrupt off, service bit set */

/* Read base and base_hi of Linux parallel port index; 0 when it exists. */
static int linux_port_address(int index, unsigned long *base, unsigned long *base_hi)
{
    char path[96];
    FILE *f;
    int n;
    snprintf(path, sizeof(path), PP_PROC_FMT, index);
    f = fopen(path, "r");
    if (!f)
        return -ENOENT;
    n = fscanf(f, "%lu %lu", base, base_hi);
    fclose(f);
    if (n < 1)
        return -ENOENT;
    if (n < 2)
        *base_hi = 0;
    return 0;
}

/* The Linux port index whose base is address, or -1. */
static int linux_port_at(unsigned long address, unsigned long *base_hi)
{
    unsigned long base;
    for (int i = 0; i < PP_MAX_LINUX_PORTS; i++)
        if (linux_port_address(i, &base, base_hi) == 0 && base == address)
            return i;
    return -1;
}

/* Ask for raw access to count ports at address (this thread); 0 or a negative errno. */
static int raw_access(unsigned long address, unsigned long count)
{
#ifdef PP_HAVE_PORT_IO
    if (ioperm(address, count, 1) != 0)
        return -errno;
    return 0;
#else
    (void)address; (void)count;
    return -ENOSYS;
#endif
}

/* Open and claim a ppdev device; 0 or a negative errno (reported). */
static int claim(pp_io_t *io)
{
    int modes = 0;
    io->fd = open(io->device, O_RDWR);
    if (io->fd < 0) {
        int e = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "open(%s): %s\n", io->device, strerror(e));
        return -e;
    }
    if (ioctl(io->fd, PPCLAIM) != 0) {
        int e = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "ioctl(%s, PPCLAIM): %s\n", io->device, strerror(e));
        close(io->fd);
        io->fd = -1;
        return -e;
    }
    if (ioctl(io->fd, PPGETMODES, &modes) != 0)
        rtapi_print_msg(RTAPI_MSG_WARN, "ioctl(%s, PPGETMODES): %s\n", io->device, strerror(errno));
    return 0;
}

/* Locate the port a cfg entry names and claim it; 0 or a negative errno (reported). */
static int locate(pp_io_t *io, const pp_port_cfg_t *cfg)
{
    int index = -1;
    switch (cfg->where) {
    case PP_WHERE_INDEX:
        index = (int)cfg->value;
        if (linux_port_address(index, &io->base, &io->base_hi) != 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "Linux parallel port %d not found\n", index);
            return -ENOENT;
        }
        break;
    case PP_WHERE_ADDRESS:
        io->base = cfg->value;
        index = linux_port_at(cfg->value, &io->base_hi);
        io->kind = raw_access(io->base, PP_REGISTERS) == 0 ? PP_IO_RAW : PP_IO_PPDEV;
        if (index < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "No parport registered at 0x%lx. This is not always an error. Continuing.\n",
                            cfg->value);
            if (io->kind != PP_IO_RAW) {
                rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: no access to I/O ports 0x%lx-0x%lx "
                                "(raw port access needs root or CAP_SYS_RAWIO)\n", io->base, io->base + 2);
                return -EPERM;
            }
            return 0;
        }
        break;
    case PP_WHERE_DEVICE:
        snprintf(io->device, sizeof(io->device), "%s", cfg->device);
        if (sscanf(cfg->device, "/dev/parport%d", &index) != 1 ||
            linux_port_address(index, &io->base, &io->base_hi) != 0)
            io->base = io->base_hi = 0;
        return claim(io);
    }
    snprintf(io->device, sizeof(io->device), "/dev/parport%d", index);
    return claim(io);
}

/* Mode set-up at load: data direction for in, the ECR for epp, raw access for x. */
static int prepare_mode(pp_io_t *io, const pp_port_cfg_t *cfg)
{
    int reverse = 1;
    if (cfg->mode == PP_MODE_X && io->kind != PP_IO_RAW) {
        /* ppdev reports its own copy of the control register, not the lines */
        if (io->base == 0 || raw_access(io->base, PP_REGISTERS) != 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: %s: mode x reads the control lines, which needs raw "
                            "port access (give the base address and run as root or with CAP_SYS_RAWIO)\n",
                            io->device);
            return -EPERM;
        }
        io->kind = PP_IO_RAW;
    }
    if (cfg->mode == PP_MODE_EPP && io->base_hi != 0) {
        if (raw_access(io->base_hi + PP_ECR_OFFSET, 1) != 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: mode epp writes the ECR at 0x%lx, which needs raw "
                            "port access (root or CAP_SYS_RAWIO)\n", io->base_hi + PP_ECR_OFFSET);
            return -EPERM;
        }
#ifdef PP_HAVE_PORT_IO
        outb(PP_ECR_EPP, io->base_hi + PP_ECR_OFFSET);
#endif
    }
    if (cfg->mode == PP_MODE_IN && io->kind == PP_IO_PPDEV && ioctl(io->fd, PPDATADIR, &reverse) != 0) {
        int e = errno;
        rtapi_print_msg(RTAPI_MSG_ERR, "ioctl(%s, PPDATADIR): %s\n", io->device, strerror(e));
        return -e;
    }
    return 0;
}

/* Find, claim and prepare the port described by cfg; returns 0 or a negative errno (reported). */
int pp_io_open(pp_io_t *io, const pp_port_cfg_t *cfg)
{
    int r;
    memset(io, 0, sizeof(*io));
    io->fd = -1;
    io->kind = PP_IO_PPDEV;
    r = locate(io, cfg);
    if (r == 0)
        r = prepare_mode(io, cfg);
    if (r == 0 && io->kind == PP_IO_RAW)
        io->io_thread = pthread_self();
    if (r == 0 && cfg->mode == PP_MODE_IN && io->kind == PP_IO_RAW)
        pp_io_write_control(io, pp_io_read_control(io) | PP_CONTROL_DIR_IN);
    if (r != 0)
        pp_io_close(io);
    return r;
}

/* Release the port. */
void pp_io_close(pp_io_t *io)
{
    if (io->fd >= 0) {
        ioctl(io->fd, PPRELEASE);
        close(io->fd);
    }
    io->fd = -1;
}

/* Record the first failed register access and report it once. */
static void io_failed(pp_io_t *io, const char *what)
{
    if (io->io_errno == 0)
        io->io_errno = errno ? errno : EIO;
    if (!io->io_reported) {
        io->io_reported = 1;
        rtapi_print_msg(RTAPI_MSG_ERR, "hal_parport: %s: %s failed: %s\n",
                        io->device[0] ? io->device : "raw port", what, strerror(io->io_errno));
    }
}

/* Called at the start of every funct: gives this thread raw access if needed; 0 = usable. */
int pp_io_begin(pp_io_t *io)
{
    if (io->kind != PP_IO_RAW || pthread_equal(io->io_thread, pthread_self()))
        return io->io_errno ? -1 : 0;
    if (raw_access(io->base, PP_REGISTERS) != 0) {
        io_failed(io, "ioperm");
        return -1;
    }
    io->io_thread = pthread_self();
    return 0;
}

/* One register read through ppdev; 0 after a failure. */
static uint8_t ppdev_read(pp_io_t *io, unsigned long request, const char *what)
{
    unsigned char v = 0;
    if (ioctl(io->fd, request, &v) != 0)
        io_failed(io, what);
    return v;
}

/* One register write through ppdev. */
static void ppdev_write(pp_io_t *io, unsigned long request, unsigned char v, const char *what)
{
    if (ioctl(io->fd, request, &v) != 0)
        io_failed(io, what);
}

#ifdef PP_HAVE_PORT_IO
#define RAW_IN(io, off) inb((io)->base + (off))
#define RAW_OUT(io, v, off) outb((v), (io)->base + (off))
#else
#define RAW_IN(io, off) ((void)(io), 0)
#define RAW_OUT(io, v, off) ((void)(io), (void)(v))
#endif

/* The data register (the data lines in mode in). */
uint8_t pp_io_read_data(pp_io_t *io)
{
    return io->kind == PP_IO_RAW ? RAW_IN(io, 0) : ppdev_read(io, PPRDATA, "PPRDATA");
}

/* The status register. */
uint8_t pp_io_read_status(pp_io_t *io)
{
    return io->kind == PP_IO_RAW ? RAW_IN(io, 1) : ppdev_read(io, PPRSTATUS, "PPRSTATUS");
}

/* The control register. */
uint8_t pp_io_read_control(pp_io_t *io)
{
    return io->kind == PP_IO_RAW ? RAW_IN(io, 2) : ppdev_read(io, PPRCONTROL, "PPRCONTROL");
}

/* Write the data register. */
void pp_io_write_data(pp_io_t *io, uint8_t value)
{
    if (io->kind == PP_IO_RAW)
        RAW_OUT(io, value, 0);
    else
        ppdev_write(io, PPWDATA, value, "PPWDATA");
}

/* Write the control register (ppdev keeps the direction bit itself, set by PPDATADIR). */
void pp_io_write_control(pp_io_t *io, uint8_t value)
{
    if (io->kind == PP_IO_RAW)
        RAW_OUT(io, value, 2);
    else
        ppdev_write(io, PPWCONTROL, value & 0x0F, "PPWCONTROL");
}
