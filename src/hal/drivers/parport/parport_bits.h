/* parport_bits.h: which DB25 pins a mode uses and how they map to the data, status and control bytes. */
#ifndef PARPORT_BITS_H
#define PARPORT_BITS_H

#include <stdint.h>
#include "parport_cfg.h"

/* Pin masks: bit n stands for DB25 pin n (1..17). */
#define PP_PIN(n) (1u << (n))
#define PP_DATA_PINS 0x3FCu                          /* pins 2-9 */
#define PP_CONTROL_PINS (PP_PIN(1) | PP_PIN(14) | PP_PIN(16) | PP_PIN(17))
#define PP_STATUS_PINS (PP_PIN(10) | PP_PIN(11) | PP_PIN(12) | PP_PIN(13) | PP_PIN(15))
#define PP_CONTROL_INVERTED 0x0Bu                    /* hardware inverts pins 1, 14 and 17 */
#define PP_CONTROL_DIR_IN 0x20u                      /* control bit 5: data port reads */
#define PP_STATUS_INVERTED 0x80u                     /* hardware inverts pin 11 (busy) */

/* Which pins are outputs and which are inputs in a mode. */
typedef struct {
    uint32_t outputs;
    uint32_t inputs;
} pp_layout_t;

/* The outputs and inputs of mode. */
pp_layout_t pp_layout(pp_mode_t mode);

/* Input pins read from the three registers (only the mode's inputs are set). */
uint32_t pp_pins_from_registers(pp_mode_t mode, uint8_t data, uint8_t status, uint8_t control);

/* The data register for the logical levels of pins 2-9. */
uint8_t pp_data_from_pins(uint32_t levels);

/* The control register for the logical levels of pins 1, 14, 16, 17 in mode. */
uint8_t pp_control_from_pins(pp_mode_t mode, uint32_t levels);

/* Output levels after the reset function: reset pins go to their inverted (inactive) level. */
static inline uint32_t pp_reset_levels(uint32_t levels, uint32_t reset_mask, uint32_t invert_mask)
{
    return (levels & ~reset_mask) | (invert_mask & reset_mask);
}

#endif
