/* pure_unit.c: unit test of simple_tp, comp_table, cubic and comp_file (no HAL). */
#include <math.h>
#include <stdio.h>
#include "simple_tp.h"
#include "comp_table.h"
#include "cubic.h"
#include "comp_file.h"

#define PERIOD 0.001

/* Run one trapezoid move from 0 to target; print steps, extremes and the landing. */
static void trapezoid(double target, double vmax, double amax)
{
    simple_tp_t tp;
    double vpeak = 0, apeak = 0;
    int steps = 0, overshoot = 0;

    simple_tp_reset(&tp, 0.0);
    tp.pos_cmd = target;
    tp.max_vel = vmax;
    tp.max_acc = amax;
    tp.enable = 1;
    do {
        simple_tp_update(&tp, PERIOD);
        steps++;
        vpeak = fmax(vpeak, fabs(tp.curr_vel));
        apeak = fmax(apeak, fabs(tp.curr_acc));
        if ((target > 0 && tp.curr_pos > target) || (target < 0 && tp.curr_pos < target))
            overshoot = 1;
    } while (tp.active && steps < 100000);
    printf("move to %g at %g/%g: %d steps, peak vel %.6f, peak acc %.6f, end %.9f, %s\n", target,
           vmax, amax, steps, vpeak, apeak, tp.curr_pos, overshoot ? "overshoot" : "no overshoot");
}

/* Stopping a move half way (enable off) decelerates within the limit. */
static void stop_midway(void)
{
    simple_tp_t tp;
    double apeak = 0;
    int steps = 0;

    simple_tp_reset(&tp, 0.0);
    tp.pos_cmd = 10;
    tp.max_vel = 5;
    tp.max_acc = 50;
    tp.enable = 1;
    for (int i = 0; i < 300; i++)
        simple_tp_update(&tp, PERIOD);
    tp.enable = 0;
    while (tp.active && steps++ < 10000) {
        simple_tp_update(&tp, PERIOD);
        apeak = fmax(apeak, fabs(tp.curr_acc));
    }
    printf("stop: %d steps, peak decel %.6f, at rest at %.6f, target follows %s\n", steps, apeak,
           tp.curr_pos, tp.pos_cmd == tp.curr_pos ? "yes" : "no");
}

/* Interpolation and edges of a comp table; refused rows. */
static void comp_table(void)
{
    comp_table_t t = { 0 };

    comp_table_add(&t, -5, 0.01, -0.01);
    comp_table_add(&t, 0, 0.02, -0.02);
    comp_table_add(&t, 5, 0.0, 0.0);
    printf("comp add equal: %d, add lower: %d\n", comp_table_add(&t, 5, 0, 0),
           comp_table_add(&t, 4, 0, 0));
    double at[] = { -9, -5, -2.5, 0, 2.5, 5, 9 };
    for (int i = 0; i < 7; i++)
        printf("comp %g: forward %.4f reverse %.4f\n", at[i], comp_table_lookup(&t, at[i], 1),
               comp_table_lookup(&t, at[i], -1));
    comp_table_t full = { 0 };
    int rc = 0;
    for (int i = 0; i <= COMP_MAX_ENTRIES && rc == 0; i++)
        rc = comp_table_add(&full, i, 0, 0);
    printf("comp rows accepted: %d, then %d\n", full.count, rc);
}

/* Cubic interpolation of a ramp x = t (rate 4) reproduces the ramp one point late. */
static void cubic(void)
{
    cubic_t c;
    double vel;

    cubic_init(&c, 4, 0.0);
    for (int k = 1; k <= 6; k++) {
        cubic_add_point(&c, k * 4 * PERIOD);
        for (int s = 0; s < 4; s++) {
            double x = cubic_sample(&c, PERIOD, &vel, NULL);
            if (k >= 4)
                printf("cubic %d.%d: %.6f vel %.6f\n", k, s, x, vel);
        }
    }
}

/* Both file types, and the refusals with file:line. */
static void comp_files(void)
{
    static const char *const files[] = { "files/type0.comp", "files/type1.comp", "files/short.comp",
                                         "files/decreasing.comp", "files/missing.comp" };
    comp_row_t rows[COMP_FILE_MAX_ROWS];
    char why[256];

    for (int i = 0; i < 5; i++) {
        int type = i == 1 ? 1 : 0;
        int n = comp_file_read(files[i], 2, type, rows, COMP_FILE_MAX_ROWS, why, sizeof why);
        if (n < 0) {
            printf("%s: %s\n", files[i], why);
            continue;
        }
        printf("%s: %d rows:", files[i], n);
        for (int r = 0; r < n; r++)
            printf(" (%g %g %g)", rows[r].nominal, rows[r].forward, rows[r].reverse);
        printf("\n");
    }
    printf("type 2: %d: %s\n", comp_file_read(files[0], 2, 2, rows, 10, why, sizeof why), why);
}

int main(void)
{
    trapezoid(1.0, 10.0, 100.0);
    trapezoid(-0.25, 5.0, 100.0);
    trapezoid(0.123456, 0.7, 3.3);
    trapezoid(3.0, 1e9, 100.0);
    stop_midway();
    comp_table();
    cubic();
    comp_files();
    return 0;
}
