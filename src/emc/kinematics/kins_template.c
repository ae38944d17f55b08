/* kins_template.c: frame of LinuxCNC's halcompile-style kinematics: instances at load, the kinematics
 * pins at the first type query (made once, unlike LinuxCNC, which tries again on every query),
 * switching with kinstype.is-N made at the same time. */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_entry.h"
#include "kins_template.h"
#include "hal/components/comp_args.h"

static int count;
RTAPI_MP_INT(count, "number of instances");
static char *names = "";
RTAPI_MP_STRING(names, "names of the instances");

static int comp_id;
static int set_up;                                  /* the kinematics pins exist */
static int active_type;                             /* type selected by kinematicsSwitch */
static hal_bit_t **is_type;                         /* kinstype.is-N, NULL until set up */

/* Make kinstype.is-0..ntypes-1 with is-<active> TRUE. */
static int make_type_pins(void)
{
    int n = kins_template_def.ntypes;
    is_type = hal_malloc(n * sizeof(*is_type));
    if (!is_type)
        return -ENOMEM;
    for (int i = 0; i < n; i++) {
        int r = hal_pin_bit_newf(HAL_OUT, &is_type[i], comp_id, "kinstype.is-%d", i);
        if (r < 0)
            return r;
        *is_type[i] = i == active_type;
    }
    return 0;
}

/* The first type query makes the kinematics pins; every query reports BOTH. */
KINEMATICS_TYPE kinematicsType(void)
{
    if (!set_up) {
        int r = hal_unready(comp_id); /* items can only be added while the component is not ready */
        if (r == 0 && kins_template_def.setup)
            r = kins_template_def.setup(comp_id);
        if (r == 0 && kins_template_def.ntypes > 1)
            r = make_type_pins();
        hal_ready(comp_id);
        if (r < 0)
            rtapi_print_msg(RTAPI_MSG_ERR, "!!! %s setup failed res=%d\n", kins_template_def.name, r);
        else
            rtapi_print_msg(RTAPI_MSG_INFO, "*** %s setup ok\n", kins_template_def.name);
        set_up = 1;
    }
    return KINEMATICS_BOTH;
}

/* Joints -> world through the selected type. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    (void)fflags;
    (void)iflags;
    return kins_template_def.forward(active_type, joint, world);
}

/* World -> joints through the selected type. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    (void)iflags;
    (void)fflags;
    return kins_template_def.inverse(active_type, world, joint);
}

/* Type t was selected (kins_entry checked it): show it on kinstype.is-N (LinuxCNC's messages). */
static void switched(int t)
{
    active_type = t;
    rtapi_print_msg(RTAPI_MSG_INFO, "kinematicsSwitch:TYPE%d\n", t == 2 ? 1 : t);
    for (int i = 0; is_type && i < kins_template_def.ntypes; i++)
        *is_type[i] = i == t;
}

/* Load-time pins of every count=/names= instance. */
static int template_build(int id)
{
    comp_id = id;
    return comp_make_named(id, kins_template_def.inst_prefix, count, names, 1, kins_template_def.instance);
}

/* Register the component and make the instances; the kinematics pins come with the first type query. */
int rtapi_app_main(void)
{
    kins_entry_t entry = {kins_template_def.name, template_build, kins_template_def.ntypes - 1,
                          kins_template_def.ntypes > 1 ? switched : NULL, 1};
    return kins_entry_start(&entry);
}
