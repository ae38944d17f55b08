/* parport_bits.c: DB25 pin layout per mode and the pin <-> register bit mapping. */
#include "parport_bits.h"

/* Status register bit -> pin, bits 3..7 (after undoing the busy inversion). */
static const uint8_t status_pin[8] = { 0, 0, 0, 15, 13, 12, 10, 11 };
/* Control register bit -> pin, bits 0..3. */
static const uint8_t control_pin[4] = { 1, 14, 16, 17 };

/* The outputs and inputs of mode. */
pp_layout_t pp_layout(pp_mode_t mode)
{
    pp_layout_t l;
    switch (mode) {
    case PP_MODE_IN:
        l.outputs = PP_CONTROL_PINS;
        l.inputs = PP_DATA_PINS | PP_STATUS_PINS;
        break;
    case PP_MODE_X:
        l.outputs = PP_DATA_PINS;
        l.inputs = PP_CONTROL_PINS | PP_STATUS_PINS;
        break;
    default:
        l.outputs = PP_DATA_PINS | PP_CONTROL_PINS;
        l.inputs = PP_STATUS_PINS;
        break;
    }
    return l;
}

/* Input pins read from the three registers (only the mode's inputs are set). */
uint32_t pp_pins_from_registers(pp_mode_t mode, uint8_t data, uint8_t status, uint8_t control)
{
    uint32_t pins = 0;
    uint8_t s = status ^ PP_STATUS_INVERTED;
    uint8_t c = control ^ PP_CONTROL_INVERTED;
    for (int bit = 3; bit < 8; bit++)
        if (s & (1u << bit))
            pins |= PP_PIN(status_pin[bit]);
    if (mode == PP_MODE_IN)
        pins |= (uint32_t)data << 2;
    if (mode == PP_MODE_X)
        for (int bit = 0; bit < 4; bit++)
            if (c & (1u << bit))
                pins |= PP_PIN(control_pin[bit]);
    return pins & pp_layout(mode).inputs;
}

/* The data register for the logical levels of pins 2-9. */
uint8_t pp_data_from_pins(uint32_t levels)
{
    return (uint8_t)((levels & PP_DATA_PINS) >> 2);
}

/* The control register for the logical levels of pins 1, 14, 16, 17 in mode. */
uint8_t pp_control_from_pins(pp_mode_t mode, uint32_t levels)
{
    uint8_t c = 0;
    for (int bit = 0; bit < 4; bit++)
        if (levels & PP_PIN(control_pin[bit]))
            c |= (uint8_t)(1u << bit);
    if (mode == PP_MODE_X)
        c = 0x0F;            /* open collector inputs: every control output released high */
    c ^= PP_CONTROL_INVERTED;
    if (mode == PP_MODE_IN)
        c |= PP_CONTROL_DIR_IN;
    return c;
}
