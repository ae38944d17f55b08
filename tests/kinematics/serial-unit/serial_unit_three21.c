/* serial_unit_three21.c: unit tests of LinuxCNC's three21kins formulas (flags, round trips, singularity). */
#include <math.h>
#include <stdio.h>
#include "serial_unit.h"
#include "emc/kinematics/serial/three21_math.h"

/* LinuxCNC's default AR2-style geometry and one with every link non-zero. */
static const three21_params_t ar2 = {64.2, 305, 0, 169.77, 0, -6.25, 223.63, 36.5};
static const three21_params_t offsets = {50, 300, 40, 400, 20, -35, 250, 60};

/* Joints from forward come back from inverse given forward's flags (arm joints within +-42 degrees:
 * LinuxCNC compares the configuration angles without wrapping them, so an arm folded back over
 * its base reports other flags); the flipped wrist reaches the same pose. */
static int three21_grid(const three21_params_t *p, const char *label)
{
    int trips = 0;
    for (int n = 0; n < 300; n++) {
        double q[6], out[6], back_q[6];
        EmcPose pos, back;
        unsigned long iflags, fflags;
        for (int i = 0; i < 6; i++)
            q[i] = su_random(-170, 170) / (i < 3 ? 4 : 1);
        if (fabs(q[4]) < 3)
            continue;
        three21_forward(p, q, &pos, &iflags);
        su_check(!(iflags & THREE21_SINGULAR), label);
        su_check(three21_inverse(p, &pos, iflags, out, &fflags) == 0 && fflags == 0, label);
        su_check(su_angle_diff(q, out, 6) < 1e-6, label);
        three21_inverse(p, &pos, iflags ^ THREE21_WRIST_FLIP, back_q, &fflags);
        three21_forward(p, back_q, &back, NULL);
        su_check(su_pose_diff(&pos, &back) < 1e-6, label);
        trips++;
    }
    return trips;
}

/* Hand-checked poses of the default geometry. */
static void three21_known(void)
{
    double home[6] = {0}, up[6] = {0, -90, 90, 0, 0, 0}, q[6], keep[6] = {0, 0, 0, 25, 0, 0};
    EmcPose pos;
    unsigned long flags, fflags;
    three21_forward(&ar2, home, &pos, &flags);
    su_print_pose("three21 fwd home", 0, &pos);
    printf("three21 home flags %lu\n", flags);
    three21_forward(&ar2, up, &pos, &flags);
    su_print_pose("three21 fwd 0 -90 90 0 0 0", 0, &pos);
    printf("three21 flags %lu\n", flags);
    three21_forward(&ar2, home, &pos, NULL);
    int rc = three21_inverse(&ar2, &pos, 0, keep, &fflags);
    su_print_joints("three21 inv home keeps joint 3", rc, keep, 6);
    printf("three21 reach flag %lu\n", fflags);
    EmcPose far = {{0, 0, 5000}, 0, 0, 0, 0, 0, 0};
    rc = three21_inverse(&ar2, &far, 0, q, &fflags);
    int finite = 1;
    for (int i = 0; i < 6; i++)
        finite = finite && isfinite(q[i]);
    su_check(rc == 0 && finite, "three21 out of reach stays finite");
}

void su_three21_tests(void)
{
    three21_known();
    printf("three21 round trips ar2 %d\n", three21_grid(&ar2, "three21 ar2 round trip"));
    printf("three21 round trips offsets %d\n", three21_grid(&offsets, "three21 offsets round trip"));
}
