/* rtapi_io.c: port I/O, privileged helpers and the calls uspace does not provide. */
#include <fcntl.h>
#include <spawn.h>
#include "rtapi.h"
#include "rtapi_io.h"
#if defined(__x86_64__) || defined(__i386__)
#include <sys/io.h>
#define RTAPI_HAVE_PORT_IO 1
#endif

#ifdef RTAPI_HAVE_PORT_IO
/* Read a byte from an I/O port. */
unsigned char rtapi_inb(unsigned int port) { return inb(port); }
/* Read a 16-bit word from an I/O port. */
unsigned short rtapi_inw(unsigned int port) { return inw(port); }
/* Read a 32-bit word from an I/O port. */
unsigned int rtapi_inl(unsigned int port) { return inl(port); }
/* Write a byte to an I/O port. */
void rtapi_outb(unsigned char byte, unsigned int port) { outb(byte, port); }
/* Write a 16-bit word to an I/O port. */
void rtapi_outw(unsigned short word, unsigned int port) { outw(word, port); }
/* Write a 32-bit word to an I/O port. */
void rtapi_outl(unsigned int word, unsigned int port) { outl(word, port); }

/* Enable access to the port range (ioperm below 0x10000, else iopl(3)). */
void *rtapi_request_region(unsigned long base, unsigned long size, const char *name)
{
    int rc = base + size <= 0x10000 ? ioperm(base, size, 1) : iopl(3);

    if (rc != 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: %s: no access to I/O ports 0x%lx..0x%lx\n",
                        name ? name : "request_region", base, base + size - 1);
        return NULL;
    }
    return (void *)-1;
}

/* Drop access to the port range. */
void rtapi_release_region(unsigned long base, unsigned long size)
{
    if (base + size <= 0x10000)
        ioperm(base, size, 0);
}
#else
/* No port I/O on this architecture: reads give 0. */
unsigned char rtapi_inb(unsigned int port) { (void)port; return 0; }
/* No port I/O on this architecture: reads give 0. */
unsigned short rtapi_inw(unsigned int port) { (void)port; return 0; }
/* No port I/O on this architecture: reads give 0. */
unsigned int rtapi_inl(unsigned int port) { (void)port; return 0; }
/* No port I/O on this architecture: writes are dropped. */
void rtapi_outb(unsigned char byte, unsigned int port) { (void)byte; (void)port; }
/* No port I/O on this architecture: writes are dropped. */
void rtapi_outw(unsigned short word, unsigned int port) { (void)word; (void)port; }
/* No port I/O on this architecture: writes are dropped. */
void rtapi_outl(unsigned int word, unsigned int port) { (void)word; (void)port; }

/* No port I/O on this architecture. */
void *rtapi_request_region(unsigned long base, unsigned long size, const char *name)
{
    (void)base; (void)size;
    rtapi_print_msg(RTAPI_MSG_ERR, "rtapi: %s: no port I/O on this CPU\n", name ? name : "");
    return NULL;
}

/* No port I/O on this architecture. */
void rtapi_release_region(unsigned long base, unsigned long size)
{
    (void)base; (void)size;
}
#endif

/* open(2); OpenEMC is never setuid, so no privilege change happens. */
int rtapi_open_as_root(const char *filename, int mode)
{
    return open(filename, mode);
}

/* posix_spawn(3) with the caller's privileges. */
int rtapi_spawn_as_root(pid_t *pid, const char *path,
                        const posix_spawn_file_actions_t *file_actions,
                        const posix_spawnattr_t *attrp,
                        char *const argv[], char *const envp[])
{
    return posix_spawn(pid, path, file_actions, attrp, argv, envp);
}

/* posix_spawnp(3) with the caller's privileges. */
int rtapi_spawnp_as_root(pid_t *pid, const char *path,
                         const posix_spawn_file_actions_t *file_actions,
                         const posix_spawnattr_t *attrp,
                         char *const argv[], char *const envp[])
{
    return posix_spawnp(pid, path, file_actions, attrp, argv, envp);
}

/* RT fifos do not exist in uspace. */
int rtapi_fifo_new(int key, int module_id, unsigned long int size, char mode)
{
    (void)key; (void)module_id; (void)size; (void)mode;
    return -ENOSYS;
}

/* RT fifos do not exist in uspace. */
int rtapi_fifo_delete(int fifo_id, int module_id)
{
    (void)fifo_id; (void)module_id;
    return -ENOSYS;
}

/* Interrupt handlers do not exist in uspace. */
int rtapi_irq_new(unsigned int irq_num, int owner, void (*handler)(void))
{
    (void)irq_num; (void)owner; (void)handler;
    return -ENOSYS;
}

/* Interrupt handlers do not exist in uspace. */
int rtapi_irq_delete(unsigned int irq_num)
{
    (void)irq_num;
    return -ENOSYS;
}

/* Interrupt handlers do not exist in uspace. */
int rtapi_enable_interrupt(unsigned int irq)
{
    (void)irq;
    return -ENOSYS;
}

/* Interrupt handlers do not exist in uspace. */
int rtapi_disable_interrupt(unsigned int irq)
{
    (void)irq;
    return -ENOSYS;
}
