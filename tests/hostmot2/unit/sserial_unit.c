/* sserial_unit.c: unit test of the Smart Serial process-data packing (hm2_sserial_data.c):
   bit fields, booleans with invert, scaled and clamped analog values, encoders across wrap. */
#include <stdio.h>
#include <string.h>
#include "hm2.h"

static hal_bit_t out_bits[4], out_inv[4], in_bits[4], in_not[4], ena, ena_not, ena_inv;
static hal_float_t spin, volts;
static hal_s32_t enc_count, enc_raw;
static hal_float_t enc_pos;
static hal_bit_t enc_index, enc_reset;
static hal_bit_t *out_ptr[4], *in_ptr[4], *in_not_ptr[4];
static hm2_sserial_rec_hal_t h_out, h_ena, h_spin, h_in, h_volts, h_enc;

/* A record of the test remote. */
static void rec(hm2_sserial_rec_t *r, const char *name, int type, int dir, int bits, int offset,
                hm2_sserial_rec_hal_t *h)
{
    memset(r, 0, sizeof(*r));
    snprintf(r->name, sizeof(r->name), "%s", name);
    r->data_type = (uint8_t)type;
    r->dir = (uint8_t)dir;
    r->bits = (uint8_t)bits;
    r->bit_offset = offset;
    r->hal = h;
}

/* Remote with 4 output bits, a boolean, a 16-bit spindle value; inputs 4 bits, 8-bit volts, encoder. */
static void build(hm2_sserial_channel_t *ch, hm2_sserial_rec_t *r)
{
    for (int i = 0; i < 4; i++) {
        out_ptr[i] = &out_bits[i];
        in_ptr[i] = &in_bits[i];
        in_not_ptr[i] = &in_not[i];
    }
    h_out.bit = out_ptr;
    h_out.bit_invert = out_inv;
    h_ena.boolean = &ena;
    h_ena.boolean_not = &ena_not;
    h_spin.value = &spin;
    h_spin.scalemax = 100;
    h_spin.maxlim = 80;
    h_spin.minlim = -80;
    h_in.bit = in_ptr;
    h_in.bit_not = in_not_ptr;
    h_volts.value = &volts;
    h_volts.scalemax = 36.3;
    h_enc.count = &enc_count;
    h_enc.rawcounts = &enc_raw;
    h_enc.position = &enc_pos;
    h_enc.index_enable = &enc_index;
    h_enc.reset = &enc_reset;
    h_enc.scale = 4;
    rec(&r[0], "output", SSLBP_TYPE_BITS, SSLBP_DIR_OUT, 4, 0, &h_out);
    rec(&r[1], "spinena", SSLBP_TYPE_BOOLEAN, SSLBP_DIR_OUT, 1, 4, &h_ena);
    rec(&r[2], "spinout", SSLBP_TYPE_SIGNED, SSLBP_DIR_OUT, 16, 30, &h_spin);
    rec(&r[3], "input", SSLBP_TYPE_BITS, SSLBP_DIR_IN, 4, 0, &h_in);
    rec(&r[4], "volts", SSLBP_TYPE_UNSIGNED, SSLBP_DIR_IN, 8, 28, &h_volts);
    rec(&r[5], "mpg", SSLBP_TYPE_ENCODER, SSLBP_DIR_IN, 8, 36, &h_enc);
    memset(ch, 0, sizeof(*ch));
    ch->rec = r;
    ch->num_pd = 6;
}

/* Outputs: bits with invert, boolean, a signed value clamped to maxlim and split over registers. */
static void test_pack(hm2_sserial_channel_t *ch, uint32_t *regs)
{
    out_bits[0] = 1;
    out_bits[2] = 1;
    out_inv[3] = 1;
    ena = 1;
    spin = 50;
    for (int i = 0; i < 3; i++)
        ch->iface_write[i] = &regs[i];
    hm2_sserial_pack_outputs(ch);
    printf("pack spin 50: reg0 0x%08x reg1 0x%08x\n", regs[0], regs[1]);
    spin = 1000;
    hm2_sserial_pack_outputs(ch);
    printf("pack spin 1000 (maxlim 80): reg0 0x%08x reg1 0x%08x\n", regs[0], regs[1]);
    spin = -25;
    ena_inv = 0;
    hm2_sserial_pack_outputs(ch);
    printf("pack spin -25: reg0 0x%08x reg1 0x%08x\n", regs[0], regs[1]);
}

/* Inputs: bits and -not, scaled volts, an encoder counting across the 8-bit wrap and reset. */
static void test_unpack(hm2_sserial_channel_t *ch, uint32_t *regs)
{
    for (int i = 0; i < 3; i++)
        ch->iface_read[i] = &regs[i];
    regs[0] = 0x5u | 0xFFu << 28;   /* inputs 0 and 2; volts low nibble */
    regs[1] = 0x0u | 0xFAu << 4;     /* volts high nibble 0; encoder raw 250 */
    hm2_sserial_unpack_inputs(ch);
    printf("unpack: in %d%d%d%d not %d%d%d%d volts %.3f count %d pos %.2f\n", in_bits[0], in_bits[1],
           in_bits[2], in_bits[3], in_not[0], in_not[1], in_not[2], in_not[3], volts, enc_count, enc_pos);
    regs[1] = 0xFu | 0x04u << 4;     /* volts 0xFF; encoder raw 4: +10 across the wrap */
    hm2_sserial_unpack_inputs(ch);
    printf("unpack: volts %.3f count %d raw %d pos %.2f\n", volts, enc_count, enc_raw, enc_pos);
    enc_reset = 1;
    hm2_sserial_unpack_inputs(ch);
    enc_reset = 0;
    regs[1] = 0xFu | 0xFEu << 4;     /* raw 254: -6 */
    hm2_sserial_unpack_inputs(ch);
    printf("after reset, -6: count %d raw %d\n", enc_count, enc_raw);
}

int main(void)
{
    hm2_sserial_channel_t ch;
    hm2_sserial_rec_t r[6];
    uint32_t out[3] = {0, 0, 0}, in[3] = {0, 0, 0};
    build(&ch, r);
    test_pack(&ch, out);
    test_unpack(&ch, in);
    return 0;
}
