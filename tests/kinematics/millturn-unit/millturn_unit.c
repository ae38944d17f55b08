/* millturn_unit.c: unit tests of the millturn turning map: known poses, round trips, handedness. */
#include <stdio.h>
#include <string.h>
#include "emc/kinematics/millturn/millturn_math.h"

static int failures;

/* Print one check and count it when it failed. */
static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    if (!ok)
        failures++;
}

/* Known joints -> pose, and other axes left alone. */
static void known(void)
{
    double j[3] = {10, 20, 30};
    EmcPose p;
    memset(&p, 0, sizeof(p));
    p.c = 7;
    millturn_turn_forward(j, &p);
    printf("joints 10 20 30 -> X=%g Y=%g Z=%g C=%g\n", p.tran.x, p.tran.y, p.tran.z, p.c);
    check(p.tran.x == 30 && p.tran.y == -20 && p.tran.z == 10 && p.c == 7,
          "turning X is slide Z, Y is -slide Y, Z is slide X");
    double k[4] = {0, 0, 0, 99};
    millturn_turn_inverse(&p, k);
    check(k[0] == 10 && k[1] == 20 && k[2] == 30 && k[3] == 99, "inverse gives the slides back");
}

/* forward(inverse(p)) == p over a grid, and the map keeps X cross Y = Z (right-handed). */
static void round_trips(void)
{
    int bad = 0, n = 0;
    for (int x = -2; x <= 2; x++)
        for (int y = -2; y <= 2; y++)
            for (int z = -2; z <= 2; z++) {
                EmcPose p, q;
                double j[3];
                memset(&p, 0, sizeof(p));
                memset(&q, 0, sizeof(q));
                p.tran = (PmCartesian){x * 1.5, y * 2.25, z * -3.0};
                millturn_turn_inverse(&p, j);
                millturn_turn_forward(j, &q);
                n++;
                bad += memcmp(&p.tran, &q.tran, sizeof(p.tran)) != 0;
            }
    printf("%d poses, %d round trips differ\n", n, bad);
    check(bad == 0, "forward(inverse(p)) == p");
    double m[3][3];
    for (int k = 0; k < 3; k++) {
        double slide[3] = {0, 0, 0};
        EmcPose e;
        slide[k] = 1;
        millturn_turn_forward(slide, &e);
        m[0][k] = e.tran.x; m[1][k] = e.tran.y; m[2][k] = e.tran.z;
    }
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
               - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
               + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    check(det == 1, "the slide frame maps to a right-handed turning frame");
}

/* Run every group; the exit status reports failures. */
int main(void)
{
    known();
    round_trips();
    printf("%d failures\n", failures);
    return failures != 0;
}
