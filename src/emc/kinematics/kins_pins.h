/* kins_pins.h: make the float geometry pins of a kinematics module from a table. */
#ifndef KINS_PINS_H
#define KINS_PINS_H

#include "hal.h"

/* One float IN pin <prefix>.<name> and the value it starts with. */
typedef struct {
    const char *name;
    double default_value;
} kins_pin_def_t;

/* Make count float IN pins <prefix>.<defs[i].name> (pointers in HAL memory, *pins[i]) with
 * their defaults; 0 or negative errno. */
int kins_float_pins(int comp_id, const char *prefix, const kins_pin_def_t *defs, int count,
                    hal_float_t ***pins);
/* The same with another direction (tripodkins' pins are I/O). */
int kins_float_pins_dir(int comp_id, const char *prefix, const kins_pin_def_t *defs, int count,
                        hal_pin_dir_t dir, hal_float_t ***pins);

#endif
