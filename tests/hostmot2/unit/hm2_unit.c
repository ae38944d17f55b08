/* hm2_unit.c: unit tests of hostmot2's pure parts: config strings, LBP16, encoder, PWM, stepgen, bitfiles. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "hm2_config.h"
#include "hm2_encoder.h"
#include "hm2_firmware.h"
#include "hm2_gtag.h"
#include "hm2_pwmgen.h"
#include "hm2_stepgen_motion.h"
#include "lbp16.h"

/* One config string: the fields that changed, or the error. */
static void config_case(const char *text)
{
    hm2_config_t c;
    char err[256];
    int r = hm2_config_parse(&c, text, err, sizeof(err));
    printf("config \"%s\": ", text);
    if (r < 0) {
        printf("error %d: %s\n", r, err);
        return;
    }
    printf("enc %d sg %d width %d pwm %d dpll %d leds %d raw %d fw '%s' sserials %d modes %.8s/%.8s absencs %d\n",
           c.num_encoders, c.num_stepgens, c.stepgen_width, c.num_pwmgens, c.num_dplls, c.num_leds,
           c.enable_raw, c.firmware, c.num_sserials, c.sserial_modes[0], c.sserial_modes[2], c.num_absencs);
}

/* Config strings: defaults, numbers like strtol(0), prefixes, every error text. */
static void test_config(void)
{
    config_case("");
    config_case("num_encoders=2 num_stepgens=0x3   num_pwmgens=010 enable_rawXYZ");
    config_case("firmware=hm2/7i92/5ABOB.BIN num_dplls=0 num_leds=2 stepgen_width=4");
    config_case("sserial_port_0=0x12 sserial_port_2=xx");
    config_case("sserial_port_4=000");
    config_case("sserial_port_0");
    config_case("num_sserials=2");
    config_case("num_inmux=2");
    config_case("ssi_chan_3=pos%16u ssi_chan_3=x%2b");
    config_case("biss_chan_32=pos%16u");
    config_case("fanuc_chan_x=AA64");
    config_case("num_encoders=");
}

/* LBP16 command words hm2_eth sends, as seen on the wire. */
static void test_lbp16(void)
{
    printf("lbp16 read 3 words: 0x%04X\n", lbp16_command(false, true, 0, 4, true, 3));
    printf("lbp16 write 1 word: 0x%04X\n", lbp16_command(true, true, 0, 4, true, 1));
    printf("lbp16 board name: 0x%04X\n", lbp16_command(false, true, 7, 2, true, 8));
    printf("lbp16 mac: 0x%04X\n", lbp16_command(false, true, 2, 2, true, 3));
    printf("lbp16 rx udp count: 0x%04X\n", lbp16_command(false, true, 6, 2, false, 1));
    printf("lbp16 seq write: 0x%04X seq echo: 0x%04X\n", lbp16_command(true, true, 4, 2, true, 2),
           lbp16_command(false, true, 4, 2, true, 4));
    lbp16_packet_t p;
    lbp16_cmd_t c;
    uint32_t word = 0x12345678;
    lbp16_reset(&p);
    lbp16_add_read(&p, 0, 4, 0x1000, 2, true);
    lbp16_add_write(&p, 4, 2, 0x10, &word, 2, true);
    int n = lbp16_decode(p.data, p.len, &c);
    printf("lbp16 packet: %d bytes, reply %d; first: %d write %d space %d size %d inc %d count %d addr 0x%04X\n",
           p.len, p.reply_len, n, c.write, c.space, c.elem_bytes, c.inc, c.count, c.addr);
    n = lbp16_decode(p.data + 4, p.len - 4, &c);
    printf("lbp16 second: %d write %d space %d size %d count %d addr 0x%04X\n", n, c.write, c.space,
           c.elem_bytes, c.count, c.addr);
    printf("lbp16 count 0 rejected: %d, 128 rejected: %d\n", lbp16_decode((const uint8_t *)"\x00\x42", 2, &c),
           lbp16_add_read(&p, 0, 4, 0, 128, true));
    int full = 0;
    lbp16_reset(&p);
    while (lbp16_add_write(&p, 0, 4, 0, &word, 1, true) == 0)
        full++;
    printf("lbp16 writes in a 1400-byte datagram: %d\n", full);
}

/* Encoder registers and the timestamp velocity estimator. */
static void test_encoder(void)
{
    uint32_t got;
    printf("tsdiv 100 MHz: %u, hires: %u\n", hm2_encoder_timestamp_divider(100000000, false),
           hm2_encoder_timestamp_divider(100000000, true));
    uint32_t rate = hm2_encoder_filter_rate(100000000, 25000000, &got);
    printf("filter 25 MHz: %u (achieved %u)", rate, got);
    rate = hm2_encoder_filter_rate(100000000, 33333333, &got);
    printf("; 33.3 MHz: 0x%X (achieved %u)", rate, got);
    rate = hm2_encoder_filter_rate(100000000, 1, &got);
    printf("; 1 Hz: 0x%X (achieved %u)\n", rate, got);
    printf("skew 25 ns: %u, 1 us: %u\n", hm2_encoder_skew_bits(100000000, 25), hm2_encoder_skew_bits(100000000, 1000));
    printf("event ticks (epoch 3, tsc 100, ts 50): %lld; (ts 200, before rollover): %lld\n",
           (long long)hm2_encoder_event_ticks(3, 100, 50), (long long)hm2_encoder_event_ticks(3, 100, 200));
    hm2_encoder_vel_t v = {0};
    double off, vel = 0;
    vel = hm2_encoder_velocity(&v, vel, 10, true, 1000, 1000, 1e-6, 1.0, 0.5, &off);
    printf("first count from stopped: velocity %g state %d\n", vel, v.state);
    vel = hm2_encoder_velocity(&v, vel, 20, true, 2000, 2000, 1e-6, 1.0, 0.5, &off);
    printf("10 counts in 1000 ticks of 1 us: velocity %g\n", vel);
    vel = hm2_encoder_velocity(&v, vel, 20, false, 2000, 2500, 1e-6, 1.0, 0.5, &off);
    printf("no count 0.5 ms later: velocity %g interp %g\n", vel, off);
    vel = hm2_encoder_velocity(&v, vel, 20, false, 2000, 202000, 1e-6, 1.0, 0.5, &off);
    printf("no count 200 ms later: velocity %g (<= 1 count / 0.2 s)\n", vel);
    vel = hm2_encoder_velocity(&v, vel, 19, true, 203000, 203000, 1e-6, 1.0, 0.5, &off);
    printf("reversal by one count: velocity %g\n", vel);
    vel = hm2_encoder_velocity(&v, 3.0, 19, false, 203000, 703000, 1e-6, 1.0, 0.5, &off);
    printf("0.5 s without counts: velocity %g state %d\n", vel, v.state);
}

/* PWMGen rate choice and register encodings (LinuxCNC's observed values). */
static void test_pwmgen(void)
{
    hm2_pwmgen_rate_t r = hm2_pwmgen_pwm_rate(200000000, 20000);
    printf("pwm 20 kHz @200 MHz: dds 0x%X bits %u note %d\n", r.dds, r.bits, r.note);
    r = hm2_pwmgen_pwm_rate(200000000, 100000);
    printf("pwm 100 kHz: dds %u bits %u\n", r.dds, r.bits);
    r = hm2_pwmgen_pwm_rate(200000000, 10000000);
    printf("pwm 10 MHz: dds %u bits %u f %u note %d\n", r.dds, r.bits, r.frequency, r.note);
    r = hm2_pwmgen_pwm_rate(200000000, 0);
    printf("pwm 0 Hz: f %u note %d\n", r.frequency, r.note);
    r = hm2_pwmgen_pdm_rate(200000000, 20000);
    printf("pdm 20 kHz: dds %u; ", r.dds);
    r = hm2_pwmgen_pdm_rate(200000000, 1);
    printf("1 Hz: dds %u f %u note %d; ", r.dds, r.frequency, r.note);
    r = hm2_pwmgen_pdm_rate(200000000, 300000000);
    printf("300 MHz: dds %u note %d\n", r.dds, r.note);
    printf("mode pwm/12: 0x%02X up-down/9: 0x%02X pdm: 0x%02X dir-pwm/10 dither: 0x%02X\n",
           hm2_pwmgen_mode_word(1, 12, false), hm2_pwmgen_mode_word(2, 9, false),
           hm2_pwmgen_mode_word(3, 12, false), hm2_pwmgen_mode_word(4, 10, true));
    printf("value 0.5/12: 0x%08X -0.5: 0x%08X 2.0: 0x%08X offset 0: 0x%08X dither 1.0: 0x%08X\n",
           hm2_pwmgen_value_register(0.5, 12, false, false), hm2_pwmgen_value_register(-0.5, 12, false, false),
           hm2_pwmgen_value_register(2.0, 12, false, false), hm2_pwmgen_value_register(0.0, 12, true, false),
           hm2_pwmgen_value_register(1.0, 12, false, true));
}

/* Stepgen: LinuxCNC's rate register and a position move that settles on its target. */
static void test_stepgen(void)
{
    printf("rate scale 100 v 10 @100 MHz: %u, v -10: 0x%08X\n", hm2_stepgen_rate_register(10, 100, 1e8),
           hm2_stepgen_rate_register(-10, 100, 1e8));
    printf("velocity mode 5 from 0 (maxaccel 100, 1 ms): %g; unlimited: %g\n",
           hm2_stepgen_velocity_velocity(5, 0, 100, 1e-3), hm2_stepgen_velocity_velocity(5, 0, 0, 1e-3));
    double pos = 0, vel = 0, old = 0, peak = 0, overshoot = 0, dt = 1e-3;
    int settled = -1;
    for (int i = 0; i < 3000; i++) {
        double cmd = 1.0;
        vel = hm2_stepgen_position_velocity(cmd, old, pos, vel, 10.0, dt, NULL);
        old = cmd;
        if (vel > 5)
            vel = 5;
        pos += vel * dt;
        peak = fabs(vel) > peak ? fabs(vel) : peak;
        overshoot = pos - 1.0 > overshoot ? pos - 1.0 : overshoot;
        if (settled < 0 && fabs(pos - 1.0) < 1e-6 && fabs(vel) < 1e-6)
            settled = i;
    }
    printf("move to 1.0 (maxvel 5, maxaccel 10): settled %s, final %.6f, peak velocity %.3f, overshoot < 1e-3: %d\n",
           settled > 0 && settled < 1500 ? "within 1.5 s" : "NOT", pos, peak, overshoot < 1e-3);
    hm2_stepgen_debug_t d;
    double v = hm2_stepgen_position_velocity(0.01, 0.0, 0.0, 0.0, 0.0, 1e-3, &d);
    printf("one cycle, maxaccel 0: v %g ff %g vel_error %g s_to_match %g\n", v, d.ff_vel, d.vel_error, d.s_to_match);
}

/* Bitfile parsing and part matching; gtag names. */
static void test_bitfile_and_names(void)
{
    static const uint8_t bit[] = {0x00, 0x09, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x0f, 0xf0, 0x00, 0x00, 0x01,
                                  'a', 0, 3, 'x', 'y', 0, 'b', 0, 8, '6', 's', 'l', 'x', '9', 't', 'q', 0,
                                  'e', 0, 0, 0, 2, 0xAA, 0x55};
    hm2_bitfile_t bf;
    int r = hm2_bitfile_parse(bit, sizeof(bit), &bf);
    printf("bitfile: %d design '%s' part '%s' bits %zu\n", r, bf.design, bf.part, bf.size);
    printf("bitfile truncated: %d, not a bitfile: %d\n", hm2_bitfile_parse(bit, sizeof(bit) - 1, &bf),
           hm2_bitfile_parse((const uint8_t *)"hello world, no bits", 20, &bf));
    printf("part XC6SLX9 vs 6slx9tq: %d, XC6SLX16 vs 6slx9tq: %d\n", hm2_fpga_part_matches("XC6SLX9", "6slx9tq"),
           hm2_fpga_part_matches("XC6SLX16", "6slx9tq"));
    char b1[32], b2[32], b3[32], b4[32], b5[32];
    printf("names: %s %s %s '%s' '%s' %s %s %s\n", hm2_gtag_name(5), hm2_gtag_hal_name(19), hm2_gtag_name(198),
           hm2_pin_log_name(6, 0x81, b1, sizeof(b1)), hm2_pin_alias_name(5, 0x89, b2, sizeof(b2)),
           hm2_pin_log_name(193, 0x92, b3, sizeof(b3)), hm2_pin_log_name(193, 0x03, b4, sizeof(b4)),
           hm2_pin_alias_name(99, 0x04, b5, sizeof(b5)));
}

/* Run every group in order. */
int main(void)
{
    test_config();
    test_lbp16();
    test_encoder();
    test_pwmgen();
    test_stepgen();
    test_bitfile_and_names();
    return 0;
}
