/* urdf_unit.c: genserkins URDF chains: a PUMA 560 URDF matches the closed form; bad files refused. */
#include <math.h>
#include <stdio.h>
#include "emc/kinematics/serial/arm6_math.h"
#include "emc/kinematics/serial/genser_math.h"
#include "emc/kinematics/serial/genser_urdf.h"
#include "emc/kinematics/serial/serial_rot.h"

static unsigned long long seed = 777;

/* Deterministic pseudo-random number in [lo, hi). */
static double random_in(double lo, double hi)
{
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(seed >> 11) / 9007199254740992.0;
}

/* Largest position / angle (modulo 360) difference of two poses. */
static double pose_diff(const EmcPose *x, const EmcPose *y)
{
    double d = fmax(fabs(x->tran.x - y->tran.x), fabs(x->tran.y - y->tran.y));
    d = fmax(d, fabs(x->tran.z - y->tran.z));
    d = fmax(d, fabs(serial_angle_near(x->a - y->a, 0)));
    d = fmax(d, fabs(serial_angle_near(x->b - y->b, 0)));
    return fmax(d, fabs(serial_angle_near(x->c - y->c, 0)));
}

/* The PUMA URDF (metres, scale 1000) against the PUMA closed form with D6 = 70. */
static int check_puma(void)
{
    static genser_chain_t chain;
    char why[300];
    int rc = genser_urdf_load("puma560.urdf", 1000.0, &chain, why, sizeof(why));
    printf("puma560.urdf: %d\n", rc);
    if (rc < 0)
        return 1;
    genser_params_t g;
    genser_defaults(&g);
    g.chain = &chain;
    arm6_params_t puma = {0, 300, 50, 0, 0, 70, 400, 70};
    double worst_fwd = 0, worst_inv = 0;
    for (int n = 0; n < 300; n++) {
        double q[6], start[6];
        EmcPose a, b;
        unsigned int used;
        for (int i = 0; i < 6; i++) {
            q[i] = random_in(-170, 170);
            start[i] = q[i] + random_in(-5, 5);
        }
        genser_forward(&g, q, &a);
        arm6_forward(&puma, q, &b, NULL);
        worst_fwd = fmax(worst_fwd, pose_diff(&a, &b));
        if (genser_inverse(&g, &a, start, &used) < 0)
            worst_inv = INFINITY;
        genser_forward(&g, start, &b);
        worst_inv = fmax(worst_inv, pose_diff(&a, &b));
    }
    printf("urdf forward equals the closed form: %d\n", worst_fwd < 1e-9);
    printf("urdf inverse round trips: %d\n", worst_inv < 1e-7);
    return !(worst_fwd < 1e-9 && worst_inv < 1e-7);
}

/* Every bad file is refused with a message naming it. */
static int check_refused(void)
{
    static const char *files[] = {
        "missing.urdf", "broken.urdf", "prismatic.urdf", "five.urdf",
        "seven.urdf", "branch.urdf", "zeroaxis.urdf",
    };
    int bad = 0;
    for (unsigned i = 0; i < sizeof(files) / sizeof(files[0]); i++) {
        genser_chain_t chain;
        char why[300];
        int rc = genser_urdf_load(files[i], 1000.0, &chain, why, sizeof(why));
        printf("%s: %d %s\n", files[i], rc, rc < 0 ? why : "accepted");
        bad += rc == 0;
    }
    return bad;
}

/* Run both groups. */
int main(void)
{
    int failures = check_puma() + check_refused();
    return failures != 0;
}
