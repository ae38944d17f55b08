/* hm2_serial_lookup.h: find a UART / PktUART / BSPI instance of any registered board by its name. */
#ifndef HM2_SERIAL_LOOKUP_H
#define HM2_SERIAL_LOOKUP_H

#include "hm2.h"

hm2_uart_instance_t *hm2_find_uart(const char *name, hm2_board_t **board);
hm2_pktuart_instance_t *hm2_find_pktuart(const char *name, hm2_board_t **board);
hm2_bspi_instance_t *hm2_find_bspi(const char *name, hm2_board_t **board);

#endif
