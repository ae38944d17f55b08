/* serial_pins.c: make the float geometry pins of a serial-arm kinematics module. */
#include "rtapi.h"
#include "serial_pins.h"

/* Create <prefix>.<name> float IN pins and set their defaults. */
int serial_float_pins(int comp_id, const char *prefix, const serial_pin_def_t *defs, int count,
                      hal_float_t **pins)
{
    for (int i = 0; i < count; i++) {
        int r = hal_pin_float_newf(HAL_IN, &pins[i], comp_id, "%s.%s", prefix, defs[i].name);
        if (r < 0)
            return r;
        *pins[i] = defs[i].default_value;
    }
    return 0;
}
