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

/* setp name value: write an unlinked IN/IO pin or a RW param. */
int hc_cmd_setp(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u cur, data;
    hc_value_t v;
    int dir, rc;
    (void)argc;
    rc = hal_get_p(argv[0], &type, &dir, &cur);
    if (rc < 0) {
        hc_error("parameter or pin '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
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
    int writers, rc;
    (void)argc;
    rc = hal_get_s(argv[0], &type, &cur, &writers);
    if (rc == 0)
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

/* getp name: print the value of a pin or param. */
int hc_cmd_getp(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u value;
    char buf[64];
    int dir, rc;
    (void)argc;
    rc = hal_get_p(argv[0], &type, &dir, &value);
    if (rc < 0) {
        hc_error("parameter or pin '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
    if (type == HAL_PORT)
        snprintf(buf, sizeof buf, "0");
    else
        hc_format_value_plain(type, (const void *)&value, buf, sizeof buf);
    printf("%s\n", buf);
    return 0;
}

/* gets sig: print the value of a signal (port: buffer size). */
int hc_cmd_gets(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u value;
    char buf[64];
    int writers, rc;
    (void)argc;
    rc = hal_get_s(argv[0], &type, &value, &writers);
    if (rc < 0) {
        hc_error("signal '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
    if (type == HAL_PORT)
        snprintf(buf, sizeof buf, "%u", (unsigned)value.u);
    else
        hc_format_value_plain(type, (const void *)&value, buf, sizeof buf);
    printf("%s\n", buf);
    return 0;
}

/* ptype name: print the type of a pin or param. */
int hc_cmd_ptype(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u value;
    int dir, rc;
    (void)argc;
    rc = hal_get_p(argv[0], &type, &dir, &value);
    if (rc < 0) {
        hc_error("parameter or pin '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
    printf("%s\n", hc_type_name(type));
    return 0;
}

/* stype sig: print the type of a signal. */
int hc_cmd_stype(int argc, char *argv[])
{
    hal_type_t type;
    hal_data_u value;
    int writers, rc;
    (void)argc;
    rc = hal_get_s(argv[0], &type, &value, &writers);
    if (rc < 0) {
        hc_error("signal '%s': %s", argv[0], hal_strerror(rc));
        return -1;
    }
    printf("%s\n", hc_type_name(type));
    return 0;
}
