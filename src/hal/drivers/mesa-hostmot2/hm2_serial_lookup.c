/* hm2_serial_lookup.c: the serial API names instances ("hm2_7i92.0.uart.0"); find them on any board. */
#include <string.h>
#include "hm2_serial_lookup.h"

/* UART instance called name, and its board. */
hm2_uart_instance_t *hm2_find_uart(const char *name, hm2_board_t **board)
{
    for (hm2_board_t *b = hm2_first_board(); b && name; b = b->next) {
        for (int i = 0; i < b->uart.num_instances; i++) {
            if (strcmp(b->uart.instance[i].name, name) == 0) {
                *board = b;
                return &b->uart.instance[i];
            }
        }
    }
    return NULL;
}

/* PktUART instance called name, and its board. */
hm2_pktuart_instance_t *hm2_find_pktuart(const char *name, hm2_board_t **board)
{
    for (hm2_board_t *b = hm2_first_board(); b && name; b = b->next) {
        for (int i = 0; i < b->pktuart.num_instances; i++) {
            if (strcmp(b->pktuart.instance[i].name, name) == 0) {
                *board = b;
                return &b->pktuart.instance[i];
            }
        }
    }
    return NULL;
}

/* BSPI instance called name, and its board. */
hm2_bspi_instance_t *hm2_find_bspi(const char *name, hm2_board_t **board)
{
    for (hm2_board_t *b = hm2_first_board(); b && name; b = b->next) {
        for (int i = 0; i < b->bspi.num_instances; i++) {
            if (strcmp(b->bspi.instance[i].name, name) == 0) {
                *board = b;
                return &b->bspi.instance[i];
            }
        }
    }
    return NULL;
}
