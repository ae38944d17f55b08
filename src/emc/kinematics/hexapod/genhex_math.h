/* genhex_math.h: Stewart-platform (hexapod) kinematics without HAL, as LinuxCNC's genhexkins computes them. */
#ifndef GENHEX_MATH_H
#define GENHEX_MATH_H

#include "emc/kinematics/emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

#define GENHEX_STRUTS 6
/* Hard cap on Newton steps per forward call, whatever limit-iterations says (bounded cycle time). */
#define GENHEX_MAX_ITERATIONS 1000

/* Machine geometry: joint centres and joint-axis unit vectors of the base and the platform. */
typedef struct {
    PmCartesian base[GENHEX_STRUTS];       /* base joint centres, world frame */
    PmCartesian platform[GENHEX_STRUTS];   /* platform joint centres, platform frame */
    PmCartesian base_n[GENHEX_STRUTS];     /* base joint axis unit vectors, world frame */
    PmCartesian platform_n[GENHEX_STRUTS]; /* platform joint axis unit vectors, platform frame */
    double screw_lead;                     /* strut screw lead; 0 turns the strut correction off */
    double z_offset;                       /* spindle offset + tool offset, added to every joint z */
} genhex_geom_t;

/* Stop rule and outcome of the iterative forward kinematics. */
typedef struct {
    double conv_criterion;       /* converged when every strut length error is at most this */
    double max_error;            /* give up when the summed strut error leaves +-max_error */
    unsigned limit_iterations;   /* give up after this many Newton steps (at most GENHEX_MAX_ITERATIONS) */
    unsigned iterations;         /* out: steps taken by the last call */
} genhex_solve_t;

/* Forward and inverse failures (LinuxCNC's return codes). */
enum {
    GENHEX_DEGENERATE = -1,      /* a strut <= 0 or of zero length */
    GENHEX_RUNAWAY = -2,         /* the summed strut error left +-max_error (or a singular Jacobian) */
    GENHEX_NO_CONVERGENCE = -5,  /* iteration limit reached */
};

/* Fill in the default geometry (LinuxCNC's sample hexapod). */
void genhex_default_geometry(genhex_geom_t *geom);
/* Rotation matrix Rz(c) Ry(b) Rx(a), angles in degrees, rows in m[0..2]. */
void genhex_rotation(double a_deg, double b_deg, double c_deg, double m[3][3]);
/* Pose -> six strut lengths (screw correction included, each in corrections[] when not NULL);
 * 0 or GENHEX_DEGENERATE. */
int genhex_inverse(const genhex_geom_t *geom, const EmcPose *pos, double lengths[GENHEX_STRUTS],
                   double corrections[GENHEX_STRUTS]);
/* Strut lengths -> pose by Newton-Raphson from the guess in *pos; 0 or a failure code, *pos is only
 * changed on success. */
int genhex_forward(const genhex_geom_t *geom, const double lengths[GENHEX_STRUTS], EmcPose *pos,
                   genhex_solve_t *solve);

#ifdef __cplusplus
}
#endif

#endif
