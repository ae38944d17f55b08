/* hm2_sserial_data.c: packing HAL values into a remote's process-data bits and back, per record
   type (bits, boolean, scaled analog, stream, float, encoder). Pure bit work, no I/O. */
#include <string.h>
#include "hm2.h"

/* Bit n of a register array (a missing register reads 0). */
static int get_bit(uint32_t *const *regs, int n)
{
    const uint32_t *r = regs[n / 32];
    return r ? (int)((*r >> (n % 32)) & 1u) : 0;
}

/* Set or clear bit n of a register array. */
static void put_bit(uint32_t *const *regs, int n, int v)
{
    uint32_t *r = regs[n / 32];
    if (!r)
        return;
    if (v)
        *r |= 1u << (n % 32);
    else
        *r &= ~(1u << (n % 32));
}

/* Up to 32 bits at offset. */
static uint32_t get_field(uint32_t *const *regs, int offset, int bits)
{
    uint32_t v = 0;
    for (int i = 0; i < bits && i < 32; i++)
        v |= (uint32_t)get_bit(regs, offset + i) << i;
    return v;
}

/* Store up to 32 bits at offset. */
static void put_field(uint32_t *const *regs, int offset, int bits, uint32_t v)
{
    for (int i = 0; i < bits && i < 32; i++)
        put_bit(regs, offset + i, (int)((v >> i) & 1u));
}

/* Full-scale raw value of an analog record (signed ones keep a sign bit). */
static double full_scale(const hm2_sserial_rec_t *rec)
{
    int bits = rec->bits > 32 ? 32 : rec->bits;
    if (rec->data_type == SSLBP_TYPE_SIGNED)
        bits--;
    return bits > 0 ? (double)((1ull << bits) - 1) : 1.0;
}

/* Sign-extend a bits-wide value. */
static int32_t sign_extend(uint32_t v, int bits)
{
    if (bits <= 0 || bits >= 32)
        return (int32_t)v;
    int shift = 32 - bits;
    return (int32_t)(v << shift) >> shift;
}

/* Analog output: clamp to minlim..maxlim, scale by scalemax, clamp to the raw range. */
static uint32_t analog_raw(const hm2_sserial_rec_t *rec)
{
    const hm2_sserial_rec_hal_t *h = rec->hal;
    double v = *h->value, fs = full_scale(rec);
    if (v > h->maxlim)
        v = h->maxlim;
    if (v < h->minlim)
        v = h->minlim;
    double raw = h->scalemax != 0.0 ? v / h->scalemax * fs : 0.0;
    double lo = rec->data_type == SSLBP_TYPE_SIGNED ? -fs : 0.0;
    raw = raw > fs ? fs : raw < lo ? lo : raw;
    return (uint32_t)(int32_t)(raw >= 0 ? raw + 0.5 : raw - 0.5);
}

/* Write one output record's bits. */
static void pack_record(hm2_sserial_rec_t *rec, uint32_t *const *regs)
{
    hm2_sserial_rec_hal_t *h = rec->hal;
    uint32_t v;
    switch (rec->data_type) {
    case SSLBP_TYPE_BITS:
        for (int i = 0; i < rec->bits; i++)
            put_bit(regs, rec->bit_offset + i, *h->bit[i] ^ h->bit_invert[i]);
        return;
    case SSLBP_TYPE_BOOLEAN:
        put_bit(regs, rec->bit_offset, *h->boolean ^ h->invert);
        return;
    case SSLBP_TYPE_UNSIGNED:
    case SSLBP_TYPE_SIGNED:
        put_field(regs, rec->bit_offset, rec->bits, analog_raw(rec));
        return;
    case SSLBP_TYPE_STREAM:
        put_field(regs, rec->bit_offset, rec->bits, *h->stream);
        return;
    case SSLBP_TYPE_FLOAT: {
        float f = (float)*h->value;
        memcpy(&v, &f, sizeof(v));
        put_field(regs, rec->bit_offset, rec->bits, v);
        return;
    }
    default:
        return;
    }
}

/* Encoder input: extend the raw counter, apply reset, scale to position. */
static void unpack_encoder(hm2_sserial_rec_t *rec, uint32_t raw)
{
    hm2_sserial_rec_hal_t *h = rec->hal;
    int bits = rec->bits > 32 ? 32 : rec->bits;
    if (!rec->enc_seeded) {
        rec->enc_prev_raw = raw;
        rec->enc_seeded = true;
    }
    rec->enc_count += sign_extend(raw - rec->enc_prev_raw, bits);
    rec->enc_prev_raw = raw;
    if (*h->reset)
        rec->enc_offset = (uint32_t)rec->enc_count;
    *h->rawcounts = (hal_s32_t)rec->enc_count;
    *h->count = (hal_s32_t)(rec->enc_count - (int32_t)rec->enc_offset);
    *h->position = h->scale != 0.0 ? *h->count / h->scale : 0.0;
}

/* Read one input record's bits into its pins. */
static void unpack_record(hm2_sserial_rec_t *rec, uint32_t *const *regs)
{
    hm2_sserial_rec_hal_t *h = rec->hal;
    uint32_t v = rec->data_type == SSLBP_TYPE_BITS ? 0 : get_field(regs, rec->bit_offset, rec->bits);
    float f;
    switch (rec->data_type) {
    case SSLBP_TYPE_BITS:
        for (int i = 0; i < rec->bits; i++) {
            int b = get_bit(regs, rec->bit_offset + i);
            *h->bit[i] = b;
            *h->bit_not[i] = !b;
        }
        return;
    case SSLBP_TYPE_BOOLEAN:
        *h->boolean = v & 1u;
        *h->boolean_not = !(v & 1u);
        return;
    case SSLBP_TYPE_UNSIGNED:
        *h->value = v * h->scalemax / full_scale(rec);
        return;
    case SSLBP_TYPE_SIGNED:
        *h->value = sign_extend(v, rec->bits) * h->scalemax / full_scale(rec);
        return;
    case SSLBP_TYPE_STREAM:
        *h->stream = v;
        return;
    case SSLBP_TYPE_FLOAT:
        memcpy(&f, &v, sizeof(f));
        *h->value = f;
        return;
    case SSLBP_TYPE_ENCODER:
    case SSLBP_TYPE_ENCODER_H:
        unpack_encoder(rec, v);
        return;
    default:
        return;
    }
}

/* All output records of a remote into its interface registers. */
void hm2_sserial_pack_outputs(hm2_sserial_channel_t *ch)
{
    for (int i = 0; i < ch->num_pd; i++)
        if (ch->rec[i].dir == SSLBP_DIR_OUT && ch->rec[i].hal)
            pack_record(&ch->rec[i], ch->iface_write);
}

/* All input records of a remote from its interface registers. */
void hm2_sserial_unpack_inputs(hm2_sserial_channel_t *ch)
{
    for (int i = 0; i < ch->num_pd; i++)
        if (ch->rec[i].dir != SSLBP_DIR_OUT && ch->rec[i].hal)
            unpack_record(&ch->rec[i], ch->iface_read);
}
