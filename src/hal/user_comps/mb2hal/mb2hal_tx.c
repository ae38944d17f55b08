/* mb2hal_tx.c: HAL pins of a transaction and one run of it (read into pins, or write pins out). */
#include "mb2hal.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>

#include "mb2hal_log.h"

#define MAX_BITS 2000
#define MAX_REGS 125
#define VERSION_1_1 11

/* Name of element i: a PIN_NAMES entry or the two-digit index. */
static const char *elem_name(const mb_tx_cfg_t *c, int i, char *buf, size_t size)
{
    if (c->pin_names)
        return c->pin_names[i];
    snprintf(buf, size, "%02d", i);
    return buf;
}

/* Allocates an array of n pin pointers in HAL memory. */
static void *hal_array(int n, size_t elem)
{
    return hal_malloc((long)((size_t)n * elem));
}

/* Pins of bit element i named base: VERSION 1.0 base itself, 1.1 base.bit (and base.bit-inv for reads). */
static int bit_pins(mb_tx_t *tx, int comp_id, const char *base, int i, hal_pin_dir_t dir)
{
    mb_pins_t *p = tx->pins;
    if (tx->cfg->version < VERSION_1_1)
        return hal_pin_bit_newf(dir, &p->bits[i], comp_id, "%s", base);
    int rc = hal_pin_bit_newf(dir, &p->bits[i], comp_id, "%s.bit", base);
    if (rc == 0 && dir == HAL_OUT)
        rc = hal_pin_bit_newf(dir, &p->bits_inv[i], comp_id, "%s.bit-inv", base);
    if (rc == 0 && dir == HAL_OUT)
        *p->bits_inv[i] = 1; /* the inverse of the FALSE the bit starts with */
    return rc;
}

/* Pins of register element i named base: base.float and base.int, except VERSION 1.0 writes (base, float). */
static int register_pins(mb_tx_t *tx, int comp_id, const char *base, int i, hal_pin_dir_t dir)
{
    mb_pins_t *p = tx->pins;
    if (dir == HAL_IN && tx->cfg->version < VERSION_1_1)
        return hal_pin_float_newf(dir, &p->floats[i], comp_id, "%s", base);
    int rc = hal_pin_float_newf(dir, &p->floats[i], comp_id, "%s.float", base);
    if (rc == 0)
        rc = hal_pin_s32_newf(dir, &p->ints[i], comp_id, "%s.int", base);
    return rc;
}

/* Creates the per-element pins of tx, logging each element's base name. */
static int element_pins(mb_tx_t *tx, int comp_id, const char *m, int tx_num, int init_debug)
{
    const mb_tx_cfg_t *c = tx->cfg;
    hal_pin_dir_t dir = mb2hal_code_is_read(c->code) ? HAL_OUT : HAL_IN;
    char buf[16], base[2 * MB2HAL_NAME_LEN + 24];
    int rc = 0;
    for (int i = 0; rc == 0 && i < c->nelements; i++) {
        snprintf(base, sizeof(base), "%s.%s.%s", m, c->tx_name, elem_name(c, i, buf, sizeof(buf)));
        mb_log(init_debug, MB_LOG_DEBUG, "create_each_mb_tx_hal_pins", "mb_tx_num [%d] pin_name [%s]",
               tx_num, base);
        if (mb2hal_code_is_bits(c->code))
            rc = bit_pins(tx, comp_id, base, i, dir);
        else
            rc = register_pins(tx, comp_id, base, i, dir);
    }
    return rc;
}

/* Creates the pins of transaction tx_num under module name; 0 or a negative HAL error. */
int mb_pins_create(mb_tx_t *tx, int comp_id, const char *module, int tx_num, int init_debug)
{
    const mb_tx_cfg_t *c = tx->cfg;
    char name[2 * MB2HAL_NAME_LEN + 16];
    tx->pins = hal_malloc(sizeof(mb_pins_t));
    if (!tx->pins)
        return -ENOMEM;
    tx->pins->bits = hal_array(c->nelements, sizeof(hal_bit_t *));
    tx->pins->bits_inv = hal_array(c->nelements, sizeof(hal_bit_t *));
    tx->pins->floats = hal_array(c->nelements, sizeof(hal_float_t *));
    tx->pins->ints = hal_array(c->nelements, sizeof(hal_s32_t *));
    if (!tx->pins->bits || !tx->pins->bits_inv || !tx->pins->floats || !tx->pins->ints)
        return -ENOMEM;
    snprintf(name, sizeof(name), "%s.%s.num_errors", module, c->tx_name);
    mb_log(init_debug, MB_LOG_DEBUG, "create_each_mb_tx_hal_pins", "mb_tx_num [%d] pin_name [%s]", tx_num,
           name);
    int rc = hal_pin_u32_newf(HAL_OUT, &tx->pins->num_errors, comp_id, "%s", name);
    if (rc == 0)
        rc = element_pins(tx, comp_id, module, tx_num, init_debug);
    return rc;
}

/* Register value for a float: rounded, clamped to -32768..65535, two's complement. */
static uint16_t to_register(double v)
{
    if (isnan(v))
        return 0;
    v = round(v);
    if (v < -32768.0)
        v = -32768.0;
    if (v > 65535.0)
        v = 65535.0;
    return (uint16_t)((int32_t)v & 0xffff);
}

/* Register value of write element i: the float pin, plus the int pin in VERSION 1.1. */
static uint16_t element_register(const mb_tx_t *tx, int i)
{
    double v = *tx->pins->floats[i];
    if (tx->cfg->version >= VERSION_1_1)
        v = round(v) + *tx->pins->ints[i];
    return to_register(v);
}

/* Stores read element i into its output pins. */
static void store_element(mb_tx_t *tx, int i, const uint8_t *bits, const uint16_t *regs)
{
    mb_pins_t *p = tx->pins;
    if (!mb2hal_code_is_bits(tx->cfg->code)) {
        *p->floats[i] = regs[i];
        *p->ints[i] = regs[i];
        return;
    }
    *p->bits[i] = bits[i] != 0;
    if (tx->cfg->version >= VERSION_1_1)
        *p->bits_inv[i] = bits[i] == 0;
}

/* Reads the device into the output pins. */
static int do_read(mb_tx_t *tx, modbus_t *ctx)
{
    const mb_tx_cfg_t *c = tx->cfg;
    uint8_t bits[MAX_BITS];
    uint16_t regs[MAX_REGS];
    int n = c->nelements, a = c->first_element, rc;
    if (c->code == 1)
        rc = modbus_read_bits(ctx, a, n, bits);
    else if (c->code == 2)
        rc = modbus_read_input_bits(ctx, a, n, bits);
    else if (c->code == 3)
        rc = modbus_read_registers(ctx, a, n, regs);
    else
        rc = modbus_read_input_registers(ctx, a, n, regs);
    if (rc != n)
        return -1;
    for (int i = 0; i < n; i++)
        store_element(tx, i, bits, regs);
    return 0;
}

/* Function codes 5 and 6: one single write per element, at FIRST_ELEMENT + i. */
static int write_singles(mb_tx_t *tx, modbus_t *ctx)
{
    const mb_tx_cfg_t *c = tx->cfg;
    for (int i = 0; i < c->nelements; i++) {
        int rc = c->code == 5 ? modbus_write_bit(ctx, c->first_element + i, *tx->pins->bits[i] ? 1 : 0)
                              : modbus_write_register(ctx, c->first_element + i, element_register(tx, i));
        if (rc != 1)
            return -1;
    }
    return 0;
}

/* Writes the input pins to the device. */
static int do_write(mb_tx_t *tx, modbus_t *ctx)
{
    const mb_tx_cfg_t *c = tx->cfg;
    uint8_t bits[MAX_BITS];
    uint16_t regs[MAX_REGS];
    int n = c->nelements, a = c->first_element;
    if (c->code == 5 || c->code == 6)
        return write_singles(tx, ctx);
    for (int i = 0; i < n; i++) {
        if (mb2hal_code_is_bits(c->code))
            bits[i] = *tx->pins->bits[i] ? 1 : 0;
        else
            regs[i] = element_register(tx, i);
    }
    if (c->code == 15)
        return modbus_write_bits(ctx, a, n, bits) == n ? 0 : -1;
    return modbus_write_registers(ctx, a, n, regs) == n ? 0 : -1;
}

/* Non-zero when errno is a Modbus exception reply: the device answered, the link is fine. */
static int is_exception(int err)
{
    return err >= EMBXILFUN && err <= EMBXGTAR;
}

/* Counts and reports a failed run; drops the link unless the device answered. */
static int fail(mb_tx_t *tx, int err)
{
    const mb_tx_cfg_t *c = tx->cfg;
    (*tx->pins->num_errors)++;
    if (c->debug >= 3 || (c->debug >= 1 && !tx->failing))
        fprintf(stderr, "mb2hal: [%s] %s failed: %s\n", c->section, mb2hal_code_name(c->code),
                modbus_strerror(err));
    tx->failing = 1;
    if (!is_exception(err))
        mb_link_close(tx->link);
    return -1;
}

/* Runs one Modbus transaction; 0 ok, 1 skipped, -1 failed. */
int mb_tx_run(mb_tx_t *tx)
{
    const mb_tx_cfg_t *c = tx->cfg;
    int rc = mb_link_open(tx->link, c);
    if (rc > 0)
        return 1;
    if (rc < 0)
        return fail(tx, errno);
    rc = mb2hal_code_is_read(c->code) ? do_read(tx, tx->link->ctx) : do_write(tx, tx->link->ctx);
    int err = errno;
    tx->link->last_use = mb_now();
    if (rc)
        return fail(tx, err);
    if (c->debug >= 3 || (c->debug >= 2 && tx->failing))
        fprintf(stderr, "mb2hal: [%s] %s OK\n", c->section, mb2hal_code_name(c->code));
    tx->failing = 0;
    return 0;
}
