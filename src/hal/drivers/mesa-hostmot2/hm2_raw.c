/* hm2_raw.c: enable_raw: peek and poke any register through HAL pins (B.raw.*). */
#include "rtapi_errno.h"
#include "hm2.h"

/* Export the raw pins when the config asks for them. */
int hm2_raw_setup(hm2_board_t *hm2)
{
    if (!hm2->config.enable_raw)
        return 0;
    const char *b = hm2->llio->name;
    int id = hm2->llio->comp_id;
    hm2_raw_hal_t *h = hal_malloc(sizeof(*h));
    if (!h)
        return -ENOMEM;
    hm2->raw.hal = h;
    int r = hal_pin_u32_newf(HAL_IN, &h->read_address, id, "%s.raw.read_address", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_OUT, &h->read_data, id, "%s.raw.read_data", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IN, &h->write_address, id, "%s.raw.write_address", b);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IN, &h->write_data, id, "%s.raw.write_data", b);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_IN, &h->write_strobe, id, "%s.raw.write_strobe", b);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_IO, &h->dump_state, id, "%s.raw.dump_state", b);
    if (r < 0)
        HM2_ERR(hm2, "error adding raw HAL objects, aborting\n");
    return r;
}

/* read-request: one extra read of read_address. */
void hm2_raw_queue_read(hm2_board_t *hm2)
{
    if (!hm2->raw.hal)
        return;
    hm2_queue_read(hm2, *hm2->raw.hal->read_address & 0xFFFF, &hm2->raw.read_word, 4);
}

/* read: publish the word; dump the module state when asked. */
void hm2_raw_process_read(hm2_board_t *hm2)
{
    hm2_raw_hal_t *h = hm2->raw.hal;
    if (!h)
        return;
    *h->read_data = hm2->raw.read_word;
    if (*h->dump_state) {
        hm2_print_modules(hm2);
        *h->dump_state = 0;
    }
}

/* write: the strobe writes write_data to write_address once. */
void hm2_raw_write(hm2_board_t *hm2)
{
    hm2_raw_hal_t *h = hm2->raw.hal;
    if (!h || !*h->write_strobe)
        return;
    uint32_t data = *h->write_data;
    hm2_queue_write(hm2, *h->write_address & 0xFFFF, &data, 4);
    *h->write_strobe = 0;
}
