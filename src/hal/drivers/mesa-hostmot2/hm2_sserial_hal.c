/* hm2_sserial_hal.c: the HAL pins and params of Smart Serial ports and of each remote's
   discovered records, named as LinuxCNC names them (<remote>.<record>[-NN][-not|-invert|...]). */
#include <string.h>
#include "rtapi_errno.h"
#include "hm2.h"

/* Pin direction of a record direction: the remote's inputs are HAL outputs and vice versa. */
static hal_pin_dir_t pin_dir(const hm2_sserial_rec_t *rec)
{
    if (rec->dir == SSLBP_DIR_OUT)
        return HAL_IN;
    return rec->dir == SSLBP_DIR_IO ? HAL_IO : HAL_OUT;
}

/* BITS: one bit pin per bit, -not for inputs, -invert params for outputs. */
static int export_bits(hm2_board_t *hm2, const char *base, hm2_sserial_rec_t *rec, hm2_sserial_rec_hal_t *h)
{
    int id = hm2->llio->comp_id, n = rec->bits, r = 0;
    bool out = rec->dir == SSLBP_DIR_OUT;
    h->bit = hal_malloc(n * sizeof(*h->bit));
    h->bit_not = out ? NULL : hal_malloc(n * sizeof(*h->bit_not));
    h->bit_invert = out ? hal_malloc(n * sizeof(*h->bit_invert)) : NULL;
    if (!h->bit || (!out && !h->bit_not) || (out && !h->bit_invert))
        return -ENOMEM;
    for (int i = 0; r == 0 && i < n; i++) {
        r = hal_pin_bit_newf(pin_dir(rec), &h->bit[i], id, "%s-%02d", base, i);
        if (r == 0 && out)
            r = hal_param_bit_newf(HAL_RW, &h->bit_invert[i], id, "%s-%02d-invert", base, i);
        else if (r == 0)
            r = hal_pin_bit_newf(HAL_OUT, &h->bit_not[i], id, "%s-%02d-not", base, i);
        if (r == 0 && out)
            h->bit_invert[i] = 0;
    }
    return r;
}

/* UNSIGNED/SIGNED: a float pin scaled by -scalemax; outputs clamp to -minlim..-maxlim. */
static int export_analog(hm2_board_t *hm2, const char *base, hm2_sserial_rec_t *rec, hm2_sserial_rec_hal_t *h)
{
    int id = hm2->llio->comp_id;
    int r = hal_pin_float_newf(pin_dir(rec), &h->value, id, "%s", base);
    if (r == 0)
        r = hal_param_float_newf(HAL_RW, &h->scalemax, id, "%s-scalemax", base);
    h->scalemax = rec->parm_max;
    if (r == 0 && rec->dir == SSLBP_DIR_OUT) {
        r = hal_param_float_newf(HAL_RW, &h->maxlim, id, "%s-maxlim", base);
        if (r == 0)
            r = hal_param_float_newf(HAL_RW, &h->minlim, id, "%s-minlim", base);
        h->maxlim = rec->parm_max;
        h->minlim = rec->parm_min;
    }
    return r;
}

/* BOOLEAN: a bit pin; inputs get -not, outputs an -invert param. */
static int export_boolean(hm2_board_t *hm2, const char *base, hm2_sserial_rec_t *rec, hm2_sserial_rec_hal_t *h)
{
    int id = hm2->llio->comp_id;
    int r = hal_pin_bit_newf(pin_dir(rec), &h->boolean, id, "%s", base);
    if (r == 0 && rec->dir == SSLBP_DIR_OUT)
        r = hal_param_bit_newf(HAL_RW, &h->invert, id, "%s-invert", base);
    else if (r == 0)
        r = hal_pin_bit_newf(HAL_OUT, &h->boolean_not, id, "%s-not", base);
    h->invert = 0;
    return r;
}

/* ENCODER: count, rawcounts, position, index-enable, reset; scale and counts-per-rev params. */
static int export_encoder(hm2_board_t *hm2, const char *base, hm2_sserial_rec_t *rec, hm2_sserial_rec_hal_t *h)
{
    int id = hm2->llio->comp_id;
    int r = hal_pin_s32_newf(HAL_OUT, &h->count, id, "%s.count", base);
    r = r ? r : hal_pin_s32_newf(HAL_OUT, &h->rawcounts, id, "%s.rawcounts", base);
    r = r ? r : hal_pin_float_newf(HAL_OUT, &h->position, id, "%s.position", base);
    r = r ? r : hal_pin_bit_newf(HAL_IO, &h->index_enable, id, "%s.index-enable", base);
    r = r ? r : hal_pin_bit_newf(HAL_IO, &h->reset, id, "%s.reset", base);
    r = r ? r : hal_param_float_newf(HAL_RW, &h->scale, id, "%s.scale", base);
    r = r ? r : hal_param_u32_newf(HAL_RW, &h->counts_per_rev, id, "%s.counts-per-rev", base);
    h->scale = rec->parm_max != 0.0f ? rec->parm_max : 1.0;
    h->counts_per_rev = 256;
    return r;
}

/* One process-data record's HAL objects. */
static int export_pd(hm2_board_t *hm2, hm2_sserial_channel_t *ch, hm2_sserial_rec_t *rec)
{
    char base[HAL_NAME_LEN + 1];
    rtapi_snprintf(base, sizeof(base), "%s.%s", ch->name, rec->name);
    switch (rec->data_type) {
    case SSLBP_TYPE_BITS:
        return export_bits(hm2, base, rec, rec->hal);
    case SSLBP_TYPE_UNSIGNED:
    case SSLBP_TYPE_SIGNED:
        return export_analog(hm2, base, rec, rec->hal);
    case SSLBP_TYPE_STREAM:
        return hal_pin_u32_newf(pin_dir(rec), &rec->hal->stream, hm2->llio->comp_id, "%s", base);
    case SSLBP_TYPE_BOOLEAN:
        return export_boolean(hm2, base, rec, rec->hal);
    case SSLBP_TYPE_ENCODER:
    case SSLBP_TYPE_ENCODER_H:
        return export_encoder(hm2, base, rec, rec->hal);
    case SSLBP_TYPE_FLOAT:
        return hal_pin_float_newf(pin_dir(rec), &rec->hal->value, hm2->llio->comp_id, "%s", base);
    case SSLBP_TYPE_PAD:
        return 0;
    default:
        HM2_ERR(hm2, "%s: record '%s' has unsupported data type 0x%02X\n", ch->name, rec->name,
                rec->data_type);
        return -EINVAL;
    }
}

/* One global as a param (RO when the remote only reports it). */
static int export_global(hm2_board_t *hm2, hm2_sserial_channel_t *ch, hm2_sserial_rec_t *rec)
{
    int id = hm2->llio->comp_id;
    hal_param_dir_t dir = rec->dir == SSLBP_DIR_IN ? HAL_RO : HAL_RW;
    hm2_sserial_rec_hal_t *h = rec->hal;
    uint32_t v = rec->written_global;
    if (rec->data_type == SSLBP_TYPE_FLOAT) {
        float f;
        memcpy(&f, &v, sizeof(f));
        h->param_float = f;
        return hal_param_float_newf(dir, &h->param_float, id, "%s.%s", ch->name, rec->name);
    }
    if (rec->data_type == SSLBP_TYPE_SIGNED || rec->data_type == SSLBP_TYPE_NONVOL_SIGNED) {
        int shift = 32 - (rec->bits ? rec->bits : 32);
        h->param_s32 = (int32_t)(v << shift) >> shift;
        return hal_param_s32_newf(dir, &h->param_s32, id, "%s.%s", ch->name, rec->name);
    }
    h->param_u32 = v;
    return hal_param_u32_newf(dir, &h->param_u32, id, "%s.%s", ch->name, rec->name);
}

/* A remote's records, plus its fault and comm-state pins. */
static int export_remote(hm2_board_t *hm2, hm2_sserial_channel_t *ch)
{
    int id = hm2->llio->comp_id, r = 0;
    ch->hal = hal_malloc(sizeof(*ch->hal));
    if (!ch->hal)
        return -ENOMEM;
    for (int i = 0; r == 0 && i < ch->num_pd + ch->num_globals; i++) {
        ch->rec[i].hal = hal_malloc(sizeof(*ch->rec[i].hal));
        if (!ch->rec[i].hal)
            return -ENOMEM;
        memset(ch->rec[i].hal, 0, sizeof(*ch->rec[i].hal));
        r = i < ch->num_pd ? export_pd(hm2, ch, &ch->rec[i]) : export_global(hm2, ch, &ch->rec[i]);
    }
    r = r ? r : hal_pin_bit_newf(HAL_OUT, &ch->hal->fault, id, "%s.fault", ch->name);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &ch->hal->comm_state, id, "%s.comm-state", ch->name);
    return r;
}

/* The port's run/state/fault objects and every remote's objects. */
int hm2_sserial_export_port(hm2_board_t *hm2, hm2_sserial_port_t *p)
{
    int id = hm2->llio->comp_id, r = 0;
    const char *b = hm2->llio->name;
    hm2_sserial_port_hal_t *h = p->hal = hal_malloc(sizeof(*p->hal));
    if (!h)
        return -ENOMEM;
    r = hal_pin_bit_newf(HAL_IN, &h->run, id, "%s.sserial.port-%d.run", b, p->index);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &h->port_state, id, "%s.sserial.port-%d.port_state", b, p->index);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &h->port_state2, id, "%s.sserial.port-%d.port_state2", b, p->index);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &h->port_state3, id, "%s.sserial.port-%d.port_state3", b, p->index);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &h->fault_count, id, "%s.sserial.port-%d.fault-count", b, p->index);
    r = r ? r : hal_param_u32_newf(HAL_RW, &h->fault_inc, id, "%s.sserial.port-%d.fault-inc", b, p->index);
    r = r ? r : hal_param_u32_newf(HAL_RW, &h->fault_dec, id, "%s.sserial.port-%d.fault-dec", b, p->index);
    r = r ? r : hal_param_u32_newf(HAL_RW, &h->fault_lim, id, "%s.sserial.port-%d.fault-lim", b, p->index);
    r = r ? r : hal_pin_s32_newf(HAL_OUT, &h->debug, id, "%s.%d.debug", b, p->index);
    if (r < 0) {
        HM2_ERR(hm2, "error adding Smart Serial port %d HAL objects\n", p->index);
        return r;
    }
    *h->run = 1;
    *h->port_state = (hal_u32_t)p->state;
    h->fault_inc = 10;
    h->fault_dec = 1;
    h->fault_lim = 200;
    p->prev_run = true;
    for (int c = 0; r == 0 && c < p->num_channels; c++)
        if (p->chan[c].present && (r = export_remote(hm2, &p->chan[c])) < 0)
            HM2_ERR(hm2, "error adding the HAL objects of %s\n", p->chan[c].name);
    return r;
}
