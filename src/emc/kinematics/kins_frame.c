/* kins_frame.c: entry points of non-switchable kinematics modules (see kins_frame.h). */
#include "rtapi.h"
#include "hal.h"
#include "kins_entry.h"
#include "kins_frame.h"

static KINEMATICS_TYPE frame_type;

/* Joints -> world through the module's forward kinematics. */
int kinematicsForward(const double *joint, EmcPose *world,
                      const KINEMATICS_FORWARD_FLAGS *fflags, KINEMATICS_INVERSE_FLAGS *iflags)
{
    if (kins_frame_def.forward_flags)
        return kins_frame_def.forward_flags(joint, world, fflags, iflags);
    return kins_frame_def.forward(joint, world);
}

/* World -> joints through the module's inverse kinematics. */
int kinematicsInverse(const EmcPose *world, double *joint,
                      const KINEMATICS_INVERSE_FLAGS *iflags, KINEMATICS_FORWARD_FLAGS *fflags)
{
    if (kins_frame_def.inverse_flags)
        return kins_frame_def.inverse_flags(world, joint, iflags, fflags);
    return kins_frame_def.inverse(world, joint);
}

/* The module's type (possibly changed by its check). */
KINEMATICS_TYPE kinematicsType(void)
{
    return frame_type;
}

/* Run the module's setup, reporting its failure. */
static int frame_build(int comp_id)
{
    int r = kins_frame_def.setup ? kins_frame_def.setup(comp_id) : 0;
    if (r < 0 && kins_frame_def.setup_error)
        rtapi_print_msg(RTAPI_MSG_ERR, "%s: ERROR: %s\n", kins_frame_def.name,
                        kins_frame_def.setup_error);
    return r;
}

/* Check the module params, then register the component and make its pins. */
int rtapi_app_main(void)
{
    frame_type = kins_frame_def.type;
    if (kins_frame_def.check) {
        int r = kins_frame_def.check(&frame_type);
        if (r < 0)
            return r;
    }
    kins_entry_t entry = {kins_frame_def.name, frame_build, 0, NULL, 0};
    return kins_entry_start(&entry);
}
