/* switchkins.c: module entry, kinstype.is-N pins, identity and userk kinematics for switchable kins. */
#include <string.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_entry.h"
#include "switchkins.h"

static char *coordinates = NULL;
RTAPI_MP_STRING(coordinates, "Axis letter of each joint for the identity kinematics (type 1)");
static char *sparm = NULL;
RTAPI_MP_STRING(sparm, "Module-specific setting, e.g. identityfirst");

/* Pins shared by every switchable module. */
typedef struct {
    hal_bit_t *is_type[3];  /* kinstype.is-0/1/2 */
    hal_s32_t *userk_fct;   /* userk.fct: forward calls of the user template */
    hal_s32_t *userk_ict;   /* userk.ict: inverse calls of the user template */
} switchkins_pins_t;

static switchkins_pins_t *pins;
static kins_coords_t coords;
static int active_type;      /* 0, 1 or 2 as seen by motion */
static int identity_first;   /* sparm=identityfirst: 0 means identity, 1 native */

/* The identity map in use (parsed coordinates=). */
const kins_coords_t *switchkins_coords(void)
{
    return &coords;
}

/* True when the active selection runs the module's native kinematics. */
static int native_active(void)
{
    return identity_first ? active_type == 1 : active_type == 0;
}

/* Joints -> world through the active kinematics. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    int r = 0;
    (void)fflags;
    if (native_active() && switchkins_def.native_forward_flags) {
        r = switchkins_def.native_forward_flags(joint, world, iflags);
    } else if (native_active()) {
        r = switchkins_def.native_forward(joint, world);
    } else {
        if (active_type == 2)
            *pins->userk_fct += 1;
        kins_identity_forward(&coords, joint, world);
    }
    if (r == 0 && switchkins_def.after_forward)
        r = switchkins_def.after_forward(joint);
    return r;
}

/* World -> joints through the active kinematics. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    if (native_active() && switchkins_def.native_inverse_flags)
        return switchkins_def.native_inverse_flags(world, joint, iflags, fflags);
    if (native_active())
        return switchkins_def.native_inverse(world, joint);
    if (active_type == 2)
        *pins->userk_ict += 1;
    kins_identity_inverse(&coords, world, joint);
    return 0;
}

/* Native type while it is active; identity and user kinematics do both directions. */
KINEMATICS_TYPE kinematicsType(void)
{
    return native_active() ? switchkins_def.native_type : KINEMATICS_BOTH;
}

/* Kinematics 0, 1 or 2 was selected (kins_entry checked it): show it on kinstype.is-N. */
static void switched(int new_type)
{
    active_type = new_type;
    for (int i = 0; i < 3; i++)
        *pins->is_type[i] = (i == new_type);
    if (switchkins_def.on_switch)
        switchkins_def.on_switch(new_type);
}

/* Create kinstype.is-0/1/2 and userk.fct/ict. */
static int export_common_pins(int comp_id)
{
    pins = hal_malloc(sizeof(*pins));
    if (!pins)
        return -ENOMEM;
    for (int i = 0; i < 3; i++) {
        int r = hal_pin_bit_newf(HAL_OUT, &pins->is_type[i], comp_id, "kinstype.is-%d", i);
        if (r < 0)
            return r;
    }
    int r = hal_pin_s32_newf(HAL_IO, &pins->userk_fct, comp_id, "userk.fct");
    if (r < 0)
        return r;
    return hal_pin_s32_newf(HAL_IO, &pins->userk_ict, comp_id, "userk.ict");
}

/* Make the shared and the module's pins, then start in type 0. */
static int switchkins_build(int comp_id)
{
    int r = export_common_pins(comp_id);
    if (r == 0 && switchkins_def.setup)
        r = switchkins_def.setup(comp_id, sparm ? sparm : "");
    if (r < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: setup failed (%d)\n", switchkins_def.name, r);
        return r;
    }
    switched(0);
    return 0;
}

/* Parse the arguments, make the pins, start in type 0. */
int rtapi_app_main(void)
{
    char why[160];
    const char *map = coordinates && *coordinates ? coordinates : switchkins_def.default_coordinates;
    if (kins_coords_parse(map, &coords, why, sizeof(why)) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: %s\n", switchkins_def.name, why);
        return -EINVAL;
    }
    identity_first = switchkins_def.identity_first_allowed && sparm &&
                     !strcmp(sparm, "identityfirst");
    kins_entry_t entry = {switchkins_def.name, switchkins_build, 2, switched, 0};
    return kins_entry_start(&entry);
}
