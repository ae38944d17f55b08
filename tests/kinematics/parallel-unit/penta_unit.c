/* penta_unit.c: unit tests of the pentapod math: home pose, round trips, solver limits. */
#include "unit_util.h"

/* Forward from a zero first guess; prints the pose and iteration count. */
static int forward_from_zero(const penta_geom_t *g, const double *j, EmcPose *p, unsigned *it)
{
    EmcPose zero = {{0, 0, 0}, 0, 0, 0, 0, 0, 0};
    *p = zero;
    return penta_forward(g, j, p, it);
}

/* Home pose by hand, then forward back to it. */
static void penta_home(void)
{
    const penta_geom_t *g = &penta_default_geom;
    EmcPose p = {{0, 0, 0}, 0, 0, 0, 0, 0, 0}, q;
    double j[9];
    int rc = penta_inverse(g, &p, j);
    print_joints("penta inv home", rc, j, 5);
    double radial = sqrt(418.03 * 418.03 + 324.56 * 324.56) - 80.32, axial = 895.56 + 185.5;
    printf("  strut 0 expected by hand = %.6f\n", sqrt(radial * radial + axial * axial));
    unsigned it;
    j[1] += 1.0;
    rc = forward_from_zero(g, j, &q, &it);
    print_pose("penta fwd strut 1 +1mm", rc, &q);
    printf("  converged within the limit: %s\n", it > 0 && it < 20 ? "yes" : "no");
}

/* Round trips over X Y Z A B from a first guess one servo step off (motion passes the last pose);
 * LinuxCNC's solver (forward differences, coarse Gauss-Jordan) is good to about 1e-4 near singular poses. */
static void penta_roundtrip(void)
{
    const penta_geom_t *g = &penta_default_geom;
    int bad = 0, tried = 0;
    unsigned worst = 0;
    for (int x = -100; x <= 100; x += 50)
        for (int y = -100; y <= 100; y += 50)
            for (int z = -100; z <= 100; z += 100)
                for (int a = -15; a <= 15; a += 5)
                    for (int b = -15; b <= 15; b += 5) {
                        EmcPose p = {{x, y, z}, a, b, 7, 8, 9, 10};
                        EmcPose guess = {{x + 0.01, y - 0.01, z + 0.01}, a + 0.005, b - 0.005, 0, 0, 0, 0};
                        double j[9];
                        unsigned it = 0;
                        tried++;
                        if (penta_inverse(g, &p, j) != 0 || penta_forward(g, j, &guess, &it) != 0
                            || pose_diff(&p, &guess) > 1e-4)
                            bad++;
                        worst = it > worst ? it : worst;
                    }
    printf("penta round trip: %d poses, %d wrong, iterations below 20: %s\n", tried, bad,
           worst < 20 ? "yes" : "no");
}

/* Iteration limit, divergence bound and impossible lengths all fail without touching the pose. */
static void penta_limits(void)
{
    penta_geom_t g = penta_default_geom;
    EmcPose p = {{50, -40, 30}, 10, -5, 0, 0, 0, 0}, q;
    double j[9];
    unsigned it;
    penta_inverse(&g, &p, j);
    g.limit_iterations = 1;
    q = p;
    q.tran.x = 50.5;
    int rc = penta_forward(&g, j, &q, &it);
    q.tran.x = 0;
    printf("penta limit-iterations 1 (-5): %d, pose untouched X=%g\n", rc, q.tran.x);
    g = penta_default_geom;
    g.max_error = 0.001;
    rc = forward_from_zero(&g, j, &q, &it);
    printf("penta max-error 0.001 (-2): %d\n", rc);
    g = penta_default_geom;
    double nonsense[9] = {1, 1, 1, 1, 1};
    rc = forward_from_zero(&g, nonsense, &q, &it);
    printf("penta impossible struts: %d, iterations capped: %s\n", rc,
           it <= g.limit_iterations ? "yes" : "no");
    double negative[9] = {1000, -1, 1000, 1000, 1000};
    rc = forward_from_zero(&g, negative, &q, &it);
    printf("penta strut <= 0 (-1): %d\n", rc);
}

/* Run the pentapod groups. */
void penta_tests(void)
{
    penta_home();
    penta_roundtrip();
    penta_limits();
}
