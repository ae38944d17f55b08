/* kins_frame_unit.c: the non-switchable frame (kins_frame.c, kins_entry.c, kins_pins.c) with a test module. */
#include <stdio.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "kins_frame.h"
#include "kins_entry.h"
#include "kins_pins.h"
#include "stub_hal.h"

static int check_rc;            /* what the module's check returns */
static hal_float_t **pins;      /* test.gain, test.offset */

static const kins_pin_def_t test_pin_defs[2] = {{"gain", 2.0}, {"offset", 0.5}};

/* Module params check: fails with check_rc, else makes the type INVERSE_ONLY. */
static int test_check(KINEMATICS_TYPE *type)
{
    printf("check (type %d)\n", (int)*type);
    if (check_rc)
        return check_rc;
    *type = KINEMATICS_INVERSE_ONLY;
    return 0;
}

/* Make test.gain and test.offset. */
static int test_setup(int comp_id)
{
    return kins_float_pins(comp_id, "test", test_pin_defs, 2, &pins);
}

/* X = gain * J0 + offset; the forward flag is echoed into the inverse flags. */
static int test_forward(const double *joints, EmcPose *pos, const KINEMATICS_FORWARD_FLAGS *fflags,
                        KINEMATICS_INVERSE_FLAGS *iflags)
{
    pos->tran.x = *pins[0] * joints[0] + *pins[1];
    *iflags = *fflags + 100;
    return 0;
}

/* J0 = (X - offset) / gain; -1 when gain is 0; sets the forward flag. */
static int test_inverse(const EmcPose *pos, double *joints, const KINEMATICS_INVERSE_FLAGS *iflags,
                        KINEMATICS_FORWARD_FLAGS *fflags)
{
    *fflags = *iflags + 200;
    if (*pins[0] == 0.0)
        return -1;
    joints[0] = (pos->tran.x - *pins[1]) / *pins[0];
    return 0;
}

const kins_frame_def_t kins_frame_def = {
    .name = "testkins", .type = KINEMATICS_BOTH, .check = test_check, .setup = test_setup,
    .setup_error = "cannot create pins", .forward_flags = test_forward,
    .inverse_flags = test_inverse,
};

/* Forward and inverse through the exported functions, flags passed both ways. */
static void run_kins(void)
{
    double joints[1] = {3.0};
    EmcPose pos = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
    KINEMATICS_FORWARD_FLAGS ff = 5;
    KINEMATICS_INVERSE_FLAGS fi = 0;
    int rc = kins_ops.forward(joints, &pos, &ff, &fi);
    printf("fwd rc %d x %.3f iflags %lu\n", rc, pos.tran.x, fi);
    pos.tran.x = 10.5;
    fi = 7;
    rc = kins_ops.inverse(&pos, joints, &fi, &ff);
    printf("inv rc %d j0 %.3f fflags %lu\n", rc, joints[0], ff);
    *pins[0] = 0.0;
    printf("inv with gain 0: rc %d\n", kins_ops.inverse(&pos, joints, &fi, &ff));
}

/* The ops table and the switch functions of a non-switchable module. */
static void show_ops(void)
{
    int type = (int)kins_ops.type(), switchable = kins_ops.switchable();
    int to_one = kins_ops.switch_type(1), to_bad = kins_ops.switch_type(-4);
    printf("ops name %s type %d switchable %d switch(1) %d switch(-4) %d\n", kins_ops.name,
           type, switchable, to_one, to_bad);
}

/* kins_switch_valid as the switchable frames use it. */
static void switch_valid(void)
{
    static const int cases[4][2] = {{0, 2}, {2, 2}, {3, 2}, {-1, 1}};
    for (int i = 0; i < 4; i++)
        printf("valid %d of 0..%d: %d\n", cases[i][0], cases[i][1],
               kins_switch_valid(cases[i][0], cases[i][1]));
}

/* Load (good, failing check, failing setup) and unload. */
int main(void)
{
    printf("-- load\n");
    printf("rtapi_app_main %d\n", rtapi_app_main());
    show_ops();
    printf("pins %.3f %.3f\n", *pins[0], *pins[1]);
    run_kins();
    rtapi_app_exit();
    printf("-- check fails: no component is made\n");
    check_rc = -22;
    printf("rtapi_app_main %d\n", rtapi_app_main());
    printf("-- setup fails: reported and removed\n");
    check_rc = 0;
    stub_fail_pin = "test.offset";
    printf("rtapi_app_main %d\n", rtapi_app_main());
    printf("-- switch range check\n");
    switch_valid();
    return 0;
}
