/* parallel_math.h: pure math of the delta, tripod, rose and pentapod kinematics (no HAL). */
#ifndef PARALLEL_MATH_H
#define PARALLEL_MATH_H

#include "emc/kinematics/emcpos.h"
#include "emc/kinematics/cartesian/cartesian_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Point where three spheres meet (the lower or upper of the two); -1 when they do not. */
int trilaterate(const double centre[3][3], const double radius[3], int upper, double out[3]);
/* Forward map of a three-strut machine: XYZ where the spheres meet, joints 3.. pass through. */
int trilaterate_pose(const double centre[3][3], const double radius[3], int upper,
                     const double *joints, EmcPose *pos);

/* Linear delta: towers on a circle of radius r, rods of length l. */
typedef struct {
    double l;   /* rod length */
    double r;   /* effector-centre to tower distance with the effector centred */
} lineardelta_geom_t;
/* Effector from carriage heights J0..J2; -1 when the rods cannot meet. */
int lineardelta_forward(const lineardelta_geom_t *g, const double *joints, EmcPose *pos);
/* Carriage heights for an effector position; -1 when out of reach. */
int lineardelta_inverse(const lineardelta_geom_t *g, const EmcPose *pos, double *joints);

/* Rotary delta: three motors at 0/120/240 degrees turning thighs down-positive. */
typedef struct {
    double platform_radius;   /* centre to motor axis */
    double thigh_length;      /* motor axis to knee */
    double shin_length;       /* knee to effector joint */
    double effector_radius;   /* effector centre to shin joint (the footradius pin) */
} rotarydelta_geom_t;
/* Effector from thigh angles J0..J2 (degrees); -1 when the shins cannot meet. */
int rotarydelta_forward(const rotarydelta_geom_t *g, const double *joints, EmcPose *pos);
/* Thigh angles for an effector position; -1 when out of reach. */
int rotarydelta_inverse(const rotarydelta_geom_t *g, const EmcPose *pos, double *joints);

/* Tripod: struts from (0,0,0), (bx,0,0), (cx,cy,0) to the tool point. */
typedef struct {
    double bx, cx, cy;
} tripod_geom_t;
/* Tool point from strut lengths (z >= 0, or z <= 0 when below); -1 when impossible. */
int tripod_forward(const tripod_geom_t *g, const double *joints, EmcPose *pos, int below);
/* Strut lengths for a tool point; -1 when the base points are degenerate. */
int tripod_inverse(const tripod_geom_t *g, const EmcPose *pos, double *joints);

/* Rose engine: J0 radius, J1 Z, J2 turn (degrees, unwrapped across calls). */
typedef struct {
    double revolutions;       /* whole turns the rotary joint has made */
    double theta_degrees;     /* atan2 angle of the last pose, -180..180 */
    double bigtheta_degrees;  /* unwrapped joint angle */
} rose_state_t;
/* Pose from joints; also resynchronises the turn counter to J2. */
void rose_forward(rose_state_t *s, const double *joints, EmcPose *pos);
/* Joints from a pose, J2 continuing the previous turn count. */
void rose_inverse(rose_state_t *s, const EmcPose *pos, double *joints);

#define PENTA_STRUTS 5
/* Hard cap on Newton steps per forward call, whatever limit-iterations says (bounded cycle time). */
#define PENTA_MAX_ITERATIONS 1000

/* Pentapod: five struts from base points to rings around the spindle axis (LinuxCNC's pentakins). */
typedef struct {
    double base[PENTA_STRUTS][3];    /* base joint positions, world (tool offset already added to z) */
    double ring_r[PENTA_STRUTS];     /* effector ring radius around the spindle axis */
    double ring_z[PENTA_STRUTS];     /* effector ring height along the spindle axis (tool offset added) */
    double convergence;              /* forward stops when every strut error is at most this */
    unsigned limit_iterations;       /* forward gives up after this many steps (at most PENTA_MAX_ITERATIONS) */
    double max_error;                /* forward gives up when the summed strut error leaves +-max_error */
} penta_geom_t;

/* The default pentapod geometry. */
extern const penta_geom_t penta_default_geom;
/* Strut lengths for X Y Z A B (A roll, B pitch, degrees; R = Ry(B) Rx(A)); C U V W pass to J5..J8. */
int penta_inverse(const penta_geom_t *g, const EmcPose *pos, double *joints);
/* Newton solve from the pose in *pos as the first guess; steps used in *iterations. 0, or -1 for a
 * strut <= 0, -2 when the error leaves +-max_error, -5 past limit_iterations (pose untouched). */
int penta_forward(const penta_geom_t *g, const double *joints, EmcPose *pos, unsigned *iterations);

#ifdef __cplusplus
}
#endif

#endif
