/* hm2_eth_hal.c: hm2_eth's extra HAL objects per board: packet-error pins and params, read timeout. */
#include "rtapi_errno.h"
#include "hm2_eth.h"

#define DEFAULT_ERROR_LIMIT 10
#define DEFAULT_ERROR_INCREMENT 2
#define DEFAULT_ERROR_DECREMENT 1

/* B.packet-error*, B.packet-read-timeout with their defaults. */
int hm2_eth_export_hal(hm2_eth_board_t *b)
{
    const char *n = b->llio.name;
    int id = b->comp_id;
    hm2_eth_hal_t *h = hal_malloc(sizeof(*h));
    if (!h)
        return -ENOMEM;
    int r = hal_pin_bit_newf(HAL_OUT, &h->packet_error, id, "%s.packet-error", n);
    if (r == 0)
        r = hal_pin_s32_newf(HAL_OUT, &h->packet_error_level, id, "%s.packet-error-level", n);
    if (r == 0)
        r = hal_pin_bit_newf(HAL_OUT, &h->packet_error_exceeded, id, "%s.packet-error-exceeded", n);
    if (r == 0)
        r = hal_pin_u32_newf(HAL_IO, &h->packet_error_total, id, "%s.packet-error-total", n);
    if (r == 0)
        r = hal_param_s32_newf(HAL_RW, &h->packet_error_limit, id, "%s.packet-error-limit", n);
    if (r == 0)
        r = hal_param_s32_newf(HAL_RW, &h->packet_error_increment, id, "%s.packet-error-increment", n);
    if (r == 0)
        r = hal_param_s32_newf(HAL_RO, &h->packet_error_decrement, id, "%s.packet-error-decrement", n);
    if (r == 0)
        r = hal_param_s32_newf(HAL_RW, &h->packet_read_timeout, id, "%s.packet-read-timeout", n);
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "hm2_eth: %s: error adding the packet-error HAL objects\n", n);
        return r;
    }
    h->packet_error_limit = DEFAULT_ERROR_LIMIT;
    h->packet_error_increment = DEFAULT_ERROR_INCREMENT;
    h->packet_error_decrement = DEFAULT_ERROR_DECREMENT;
    h->packet_read_timeout = HM2_ETH_DEFAULT_READ_TIMEOUT;
    b->hal = h;
    return 0;
}
