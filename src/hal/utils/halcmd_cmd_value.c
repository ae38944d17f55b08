/* halcmd_cmd_value.c: setp, sets, getp, gets, ptype and stype. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "hal.h"
#include "halcmd.h"
#include "halcmd_cmds.h"

/* "pin" or "parameter" for a direction returned by hal_get_p. */
static const char *hc_p_kind(int dir)
{
    return (dir == HAL_RO || dir == HAL_RW) ? "parameter" : "pin";
}

/* Copy a parsed value into the HAL value union for the type. */
static void hc_to_data(int type, const hc_value_t *v, hal_data_u *d)
{
    memset((void *)d, 0, sizeof *d);
    switch (type) {
    case HAL_BIT: d->b = v->b; break;
    case HAL_FLOAT: d->f = v->f; break;
    case HAL_S32: d->s = v->s32; break;
    case HAL_U32: d->u = v->u32; break;
    case HAL_S64: d->ls = v->s64; break;
    case HAL_U64: d->lu = v->u64; break;
    default: d->p = v->port; break;
    }
}

/* Look up a pin or param; logs and returns -1 when there is none of that name. */
static int hc_find_p(const char *name, hal_type_t *type, int *dir, hal_data_u *value)
{
    int rc = hal_get_p(name, type, dir, value);
    if (rc < 0) {
        hc_error("parameter or pin '%s': %s", name, hal_strerror(rc));
        return -1;
    }
    return 0;
}

/* Look up a signal; logs and returns -1 when there is none of that name. */
static int hc_find_s(const char *name, hal_type_t *type, hal_data_u *value)
{
    int writers;
    int rc = hal_get_s(name, type, value, &writers);
    if (rc < 0) {
        hc_error("signal '%s': %s", name, hal_strerror(rc));
        return -1;
    }
    return 0;
}

/* Print a value as getp/gets do; a port prints port_size instead. */
static void hc_print_value(hal_type_t type, const hal_data_u *value, unsigned port_size)
{
    char buf[64];
    if (type == HAL_PORT)
        snprintf(buf, sizeof buf, "%u", port_size);
    else
        hc_format_value_plain(type, (const void *)value, buf, sizeof buf);
    hc_print("%s\n", buf);
}

/* setp name value: write an unlinked IN/IO pin or a RW param. */
int hc_cmd_setp(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u cur, data;
    hc_value_t v;
    int dir, rc;
    (void)argc;
    if (hc_find_p(argv[0], &type, &dir, &cur) < 0)
        return -1;
    rc = hc_parse_value(type, argv[1], &v);
    if (rc == 0) {
        hc_to_data(type, &v, &data);
        rc = hal_set_p(argv[0], type, &data);
    }
    if (rc < 0) {
        hc_error("%s '%s': %s", hc_p_kind(dir), argv[0], hal_strerror(rc));
        return -1;
    }
    hc_info("%s '%s' set to %s", dir == HAL_RO || dir == HAL_RW ? "Parameter" : "Pin",
            argv[0], argv[1]);
    return 0;
}

/* sets sig value: write a signal without OUT pin, or size a port's buffer. */
int hc_cmd_sets(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u cur, data;
    hc_value_t v;
    int rc;
    (void)argc;
    if (hc_find_s(argv[0], &type, &cur) < 0)
        return -1;
    rc = hc_parse_value(type == HAL_PORT ? HAL_U32 : type, argv[1], &v);
    if (rc == 0) {
        hc_to_data(type == HAL_PORT ? HAL_U32 : type, &v, &data);
        rc = hal_set_s(argv[0], type, &data);
    }
    if (rc < 0) {
        hc_error("signal '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
    hc_info("Signal '%s' set to %s", argv[0], argv[1]);
    return 0;
}

/* What getp/gets/ptype/stype look up, and what they print of it. */
enum { HC_PIN_OR_PARAM, HC_SIGNAL };
enum { HC_PRINT_VALUE, HC_PRINT_TYPE };

/* Print the value or type of a pin/param or signal; a port shows 0 as a pin, size as a signal. */
static int hc_print_item(const char *name, int item, int what)
{
    hal_type_t type;
    hal_data_u value;
    int dir;
    int rc = item == HC_SIGNAL ? hc_find_s(name, &type, &value)
                               : hc_find_p(name, &type, &dir, &value);
    if (rc < 0)
        return -1;
    if (what == HC_PRINT_TYPE)
        hc_print("%s\n", hc_type_name(type));
    else
        hc_print_value(type, &value, item == HC_SIGNAL ? (unsigned)value.u : 0);
    return 0;
}

/* getp name: print the value of a pin or param. */
int hc_cmd_getp(int argc, char *argv[])
{
    (void)argc;
    return hc_print_item(argv[0], HC_PIN_OR_PARAM, HC_PRINT_VALUE);
}

/* gets sig: print the value of a signal. */
int hc_cmd_gets(int argc, char *argv[])
{
    (void)argc;
    return hc_print_item(argv[0], HC_SIGNAL, HC_PRINT_VALUE);
}

/* ptype name: print the type of a pin or param. */
int hc_cmd_ptype(int argc, char *argv[])
{
    (void)argc;
    return hc_print_item(argv[0], HC_PIN_OR_PARAM, HC_PRINT_TYPE);
}

/* stype sig: print the type of a signal. */
int hc_cmd_stype(int argc, char *argv[])
{
    (void)argc;
    return hc_print_item(argv[0], HC_SIGNAL, HC_PRINT_TYPE);
}
