/* parport_unit.c: prints how cfg strings parse and how pins map to the parallel port registers. */
#include <stdio.h>
#include "parport_bits.h"
#include "parport_cfg.h"

static const char *const where_names[] = { "index", "address", "device" };

/* Print the parse of one cfg string. */
static void show_cfg(const char *cfg)
{
    pp_port_cfg_t ports[PP_MAX_PORTS];
    char err[PP_ERROR_LEN];
    int n = pp_cfg_parse(cfg, ports, err);
    printf("cfg \"%s\": ", cfg);
    if (n < 0) {
        printf("error: %s\n", err);
        return;
    }
    printf("%d port(s)", n);
    for (int i = 0; i < n; i++) {
        if (ports[i].where == PP_WHERE_DEVICE)
            printf(" [%s %s %s]", where_names[ports[i].where], ports[i].device, pp_mode_name(ports[i].mode));
        else
            printf(" [%s 0x%lx %s]", where_names[ports[i].where], ports[i].value, pp_mode_name(ports[i].mode));
    }
    printf("\n");
}

/* Print a pin mask as a list of pin numbers. */
static void show_pins(const char *what, uint32_t pins)
{
    printf("%s:", what);
    for (int n = 1; n <= 17; n++)
        if (pins & PP_PIN(n))
            printf(" %d", n);
    printf("\n");
}

int main(void)
{
    const char *cfgs[] = {
        "0x378 out 0x278 in", "378_In_0_x", "parport1 epp", "/dev/parport0 X", "", "   ",
        "0x378 zz", "e000", "378 e000 0", "1 2 3", "0x10000", "0x", "0xD000 output",
        "0 1 2 3 4 5 6 7", "0 1 2 3 4 5 6 7 8", "parport", "parportx", "/dev/x_y",
    };
    for (size_t i = 0; i < sizeof(cfgs) / sizeof(cfgs[0]); i++)
        show_cfg(cfgs[i]);
    for (int m = PP_MODE_OUT; m <= PP_MODE_X; m++) {
        pp_layout_t l = pp_layout((pp_mode_t)m);
        printf("mode %s\n", pp_mode_name((pp_mode_t)m));
        show_pins("  outputs", l.outputs);
        show_pins("  inputs", l.inputs);
        show_pins("  status 0x00 data 0xA5 control 0x00", pp_pins_from_registers((pp_mode_t)m, 0xA5, 0x00, 0x00));
        show_pins("  status 0xD8 data 0x0F control 0x0B", pp_pins_from_registers((pp_mode_t)m, 0x0F, 0xD8, 0x0B));
        show_pins("  status 0x78 data 0xFF control 0xC4", pp_pins_from_registers((pp_mode_t)m, 0xFF, 0x78, 0xC4));
        printf("  control for no pins 0x%02x, for 1 0x%02x, for 14 0x%02x, for 16 0x%02x, for 17 0x%02x, all 0x%02x\n",
               pp_control_from_pins((pp_mode_t)m, 0), pp_control_from_pins((pp_mode_t)m, PP_PIN(1)),
               pp_control_from_pins((pp_mode_t)m, PP_PIN(14)), pp_control_from_pins((pp_mode_t)m, PP_PIN(16)),
               pp_control_from_pins((pp_mode_t)m, PP_PIN(17)), pp_control_from_pins((pp_mode_t)m, PP_CONTROL_PINS));
    }
    printf("data for pins 2 and 9: 0x%02x, for 3,4,5: 0x%02x\n",
           pp_data_from_pins(PP_PIN(2) | PP_PIN(9) | PP_PIN(1)), pp_data_from_pins(PP_PIN(3) | PP_PIN(4) | PP_PIN(5)));
    show_pins("reset of 2,3,4 (reset 2,3; 3 inverted)",
              pp_reset_levels(PP_PIN(2) | PP_PIN(3) | PP_PIN(4), PP_PIN(2) | PP_PIN(3), PP_PIN(3)));
    show_pins("reset of none (reset 2,5; 5 inverted)", pp_reset_levels(0, PP_PIN(2) | PP_PIN(5), PP_PIN(5)));
    return 0;
}
