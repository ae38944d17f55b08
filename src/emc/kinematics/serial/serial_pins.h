/* serial_pins.h: HAL pin helpers shared by the serial-arm kinematics modules. */
#ifndef SERIAL_PINS_H
#define SERIAL_PINS_H

#include "hal.h"

/* One float IN pin <prefix>.<name> holding a geometry value. */
typedef struct {
    const char *name;
    double default_value;
} serial_pin_def_t;

/* Make count float IN pins from defs into pins[] with their defaults; 0 or negative errno. */
int serial_float_pins(int comp_id, const char *prefix, const serial_pin_def_t *defs, int count,
                      hal_float_t **pins);

#endif
