/* hm2_led.c: the board LEDs (GTag 128): pins B.led.CR01..., LED i = register bit 31-i. */
#include "rtapi_errno.h"
#include "hm2.h"

/* Parse the LED descriptor; the count is limited by the board driver's LEDs and num_leds. */
int hm2_led_parse_md(hm2_board_t *hm2, int md_index)
{
    const hm2_md_t *md = &hm2->md[md_index];
    hm2_led_t *l = &hm2->led;
    if (!hm2_md_is_consistent_or_complain(hm2, md_index, 0, 1, 4, 0x00))
        return -EINVAL;
    int n = hm2->llio->num_leds;
    if (hm2->config.num_leds >= 0 && hm2->config.num_leds < n)
        n = hm2->config.num_leds;
    if (hm2->config.num_leds > hm2->llio->num_leds)
        HM2_ERR(hm2, "There are only %d LEDs on this board type, defaulting to %d\n",
                hm2->llio->num_leds, n);
    if (n <= 0)
        return 0;
    l->num_instances = n;
    l->led_addr = md->base_address;
    l->hal = hal_malloc(n * sizeof(*l->hal));
    if (!l->hal)
        return -ENOMEM;
    for (int i = 0; i < n; i++) {
        int r = hal_pin_bit_newf(HAL_IN, &l->hal[i].led, hm2->llio->comp_id, "%s.led.CR%02d",
                                 hm2->llio->name, i + 1);
        if (r < 0) {
            HM2_ERR(hm2, "error adding LED HAL objects, aborting\n");
            return r;
        }
    }
    return n;
}

/* Write the LED register when a pin changed (and once after every force-write). */
void hm2_led_write(hm2_board_t *hm2)
{
    hm2_led_t *l = &hm2->led;
    if (l->num_instances == 0)
        return;
    uint32_t reg = 0;
    for (int i = 0; i < l->num_instances; i++)
        if (*l->hal[i].led)
            reg |= 1u << (31 - i);
    if (l->ever_written && reg == l->written)
        return;
    hm2_queue_write(hm2, l->led_addr, &reg, 4);
    l->written = reg;
    l->ever_written = true;
}
