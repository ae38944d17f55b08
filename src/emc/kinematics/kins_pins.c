/* kins_pins.c: make the float geometry pins of a kinematics module from a table. */
#include "rtapi.h"
#include "kins_pins.h"

/* Make count float pins of direction dir, <prefix>.<defs[i].name>, with their defaults; 0 or
 * negative errno. */
int kins_float_pins_dir(int comp_id, const char *prefix, const kins_pin_def_t *defs, int count,
                        hal_pin_dir_t dir, hal_float_t ***pins)
{
    hal_float_t **made = hal_malloc(count * sizeof(*made));
    if (!made)
        return -ENOMEM;
    for (int i = 0; i < count; i++) {
        int r = hal_pin_float_newf(dir, &made[i], comp_id, "%s.%s", prefix, defs[i].name);
        if (r < 0)
            return r;
        *made[i] = defs[i].default_value;
    }
    *pins = made;
    return 0;
}

/* Make count float IN pins <prefix>.<defs[i].name> with their defaults; 0 or negative errno. */
int kins_float_pins(int comp_id, const char *prefix, const kins_pin_def_t *defs, int count,
                    hal_float_t ***pins)
{
    return kins_float_pins_dir(comp_id, prefix, defs, count, HAL_IN, pins);
}
