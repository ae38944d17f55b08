/* cubic.h: cubic (Hermite) interpolation of trajectory points to servo rate, pure. */
#ifndef CUBIC_H
#define CUBIC_H

/* Interpolates between the two middle of the last four trajectory points
 * (one trajectory period of delay); rate servo samples per trajectory point. */
typedef struct cubic {
    int rate;
    int step;           /* samples taken from the current interval */
    double p[4];        /* oldest .. newest point */
    double a, b, c, d;  /* the interval's polynomial in t = 0..1 */
} cubic_t;

/* Start at rest at pos. */
void cubic_init(cubic_t *c, int rate, double pos);
/* Non-zero when the next sample needs a new trajectory point first. */
int cubic_needs_point(const cubic_t *c);
/* Add the next trajectory point. */
void cubic_add_point(cubic_t *c, double pos);
/* Non-zero when the last four points are equal and the interval is used up (at rest). */
int cubic_settled(const cubic_t *c);
/* Next servo sample (position), with velocity and acceleration per second. */
double cubic_sample(cubic_t *c, double servo_period, double *vel, double *acc);

#endif
