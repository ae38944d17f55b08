/* hm2_test.c: a fake board whose register file holds a test pattern, to exercise hm2_register. */
#include <stdlib.h>
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "rtapi_errno.h"
#include "hal.h"
#include "hostmot2.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Test patterns for the hostmot2 driver core");

#define IMAGE_BYTES 65536
#define IDROM 0x400

static int test_pattern = 0;
RTAPI_MP_INT(test_pattern, "the test pattern to present (0-14)");
static char *config[2];
RTAPI_MP_ARRAY_STRING(config, 2, "config string for the board (only the first is used)");

static int comp_id;
static hm2_llio_t *llio;
static uint8_t *image;

/* Store a little-endian word in the register image. */
static void set32(uint32_t addr, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        image[addr + i] = (uint8_t)(v >> (8 * i));
}

/* Cookie, "HOSTMOT2", IDROM offset 0x400 and IDROM type 2. */
static void good_header(void)
{
    set32(0x100, 0x55AACAFE);
    memcpy(image + 0x104, "HOSTMOT2", 8);
    set32(0x10C, IDROM);
    set32(IDROM, 2);
}

/* IDROM geometry words: ports, width, port width, clocks. */
static void geometry(uint32_t ports, uint32_t width, uint32_t port_width, uint32_t lo, uint32_t hi)
{
    set32(IDROM + 0x1C, ports);
    set32(IDROM + 0x20, width);
    set32(IDROM + 0x24, port_width);
    set32(IDROM + 0x28, lo);
    set32(IDROM + 0x2C, hi);
}

/* Patterns 0-10: each adds one more correct piece, so the next IDROM check fails. */
static void pattern_1(void) { set32(0x100, 0x55AACAFE); }
static void pattern_2(void) { pattern_1(); memcpy(image + 0x104, "HOSTMOT2", 8); }
static void pattern_3(void) { pattern_2(); set32(0x10C, IDROM); set32(IDROM, 0x1234); }
static void pattern_4(void) { good_header(); }
static void pattern_5(void) { good_header(); geometry(0, 0, 29, 0, 0); }
static void pattern_6(void) { good_header(); geometry(0, 0, 24, 0, 0); }
static void pattern_7(void) { good_header(); geometry(1, 99, 24, 0, 0); }
static void pattern_8(void) { good_header(); geometry(2, 48, 24, 0, 0); }
static void pattern_9(void) { good_header(); geometry(1, 24, 24, 12345, 0); }
static void pattern_10(void) { good_header(); geometry(1, 24, 24, 2000000, 0); }

/* Six 24-pin connectors, pin descriptors all zero. */
static void pattern_11(void)
{
    static const char *names[6] = {"P4", "P5", "P6", "P9", "P8", "P7"};
    good_header();
    set32(IDROM + 0x04, 0x40);
    set32(IDROM + 0x08, 0x1C0);
    geometry(6, 144, 24, 2000000, 20000000);
    llio->num_ioport_connectors = 6;
    for (int i = 0; i < 6; i++)
        llio->ioport_connector_name[i] = names[i];
}

/* A valid board without modules: 24 IOPort pins, no IOPort module descriptor. */
static void pattern_12(void)
{
    good_header();
    set32(IDROM + 0x04, 0x40);
    set32(IDROM + 0x08, 0x200);
    geometry(1, 24, 24, 2000000, 20000000);
    for (int i = 0; i < 24; i++)
        set32(IDROM + 0x200 + 4 * i, 0x03000000);
    llio->ioport_connector_name[0] = "P3";
}

/* 13: the driver claims 5 pins per connector; 14: 37 pins, but no IO ports in the IDROM; 0: all zero. */
static void pattern_13(void) { good_header(); geometry(0, 0, 24, 0, 0); llio->pins_per_connector = 5; }
static void pattern_14(void) { good_header(); geometry(0, 0, 37, 0, 0); llio->pins_per_connector = 37; }
static void pattern_0(void) { }

static void (*const patterns[])(void) = {
    pattern_0, pattern_1, pattern_2, pattern_3, pattern_4, pattern_5, pattern_6, pattern_7,
    pattern_8, pattern_9, pattern_10, pattern_11, pattern_12, pattern_13, pattern_14,
};

/* Reads come from the image. */
static int test_read(hm2_llio_t *l, uint32_t addr, void *buf, int size)
{
    (void)l;
    if (size < 0 || addr + (uint32_t)size > IMAGE_BYTES)
        return -EINVAL;
    memcpy(buf, image + addr, size);
    return 0;
}

/* Writes are accepted and forgotten. */
static int test_write(hm2_llio_t *l, uint32_t addr, const void *buf, int size)
{
    (void)l; (void)buf;
    return (size < 0 || addr + (uint32_t)size > IMAGE_BYTES) ? -EINVAL : 0;
}

/* Programming "succeeds" without doing anything. */
static int test_program(hm2_llio_t *l, const void *bits, size_t size)
{
    (void)l; (void)bits; (void)size;
    return 0;
}

/* Reset does nothing on a fake board. */
static int test_reset(hm2_llio_t *l)
{
    (void)l;
    return 0;
}

static const hm2_llio_ops_t test_ops = {
    .version = HM2_LLIO_OPS_VERSION,
    .read = test_read,
    .write = test_write,
    .program_fpga = test_program,
    .reset = test_reset,
};

/* Build the fake board for test_pattern and register it. */
int rtapi_app_main(void)
{
    rtapi_print_msg(RTAPI_MSG_ERR, "hm2_test: loading HostMot2 test driver with test pattern %d\n",
                    test_pattern);
    if (test_pattern < 0 || test_pattern >= (int)(sizeof(patterns) / sizeof(patterns[0]))) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_test: unknown test pattern %d\n", test_pattern);
        return -ENODEV;
    }
    comp_id = hal_init("hm2_test");
    if (comp_id < 0)
        return comp_id;
    image = calloc(1, IMAGE_BYTES);
    llio = hal_malloc(sizeof(*llio));
    if (!image || !llio) {
        hal_exit(comp_id);
        free(image);
        return -ENOMEM;
    }
    strcpy(llio->name, "hm2_test.0");
    llio->comp_id = comp_id;
    llio->num_ioport_connectors = 1;
    llio->pins_per_connector = 24;
    llio->ioport_connector_name[0] = "P99";
    llio->fpga_part_number = "none";
    llio->num_leds = 0;
    llio->threadsafe = true;
    llio->ops = &test_ops;
    patterns[test_pattern]();
    int r = hm2_register(llio, config[0]);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_test.0: hm2_test fails HM2 registration\n");
        hal_exit(comp_id);
        free(image);
        return -EIO;
    }
    rtapi_print("hm2_test.0: initialized hm2 test-pattern %d\n", test_pattern);
    hal_ready(comp_id);
    return 0;
}

/* Unregister the board and remove the component. */
void rtapi_app_exit(void)
{
    hm2_unregister(llio);
    free(image);
    rtapi_print("hm2_test: driver unloaded\n");
    hal_exit(comp_id);
}
