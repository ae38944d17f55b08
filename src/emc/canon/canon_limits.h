/* canon_limits.h: velocity, acceleration and jerk a move may have along its path, from the per-axis limits. */
#ifndef CANON_LIMITS_H
#define CANON_LIMITS_H

#ifdef __cplusplus
extern "C" {
#endif

#define CANON_AXES 9            /* X Y Z A B C U V W */
#define CANON_LIMIT_NONE 1e99   /* "no limit" as LinuxCNC's INI defaults */

/* Per-axis limits in machine units (mu/s, mu/s^2, mu/s^3; jerk 0 = none configured). */
typedef struct canon_axis_limits {
    double vel[CANON_AXES];
    double acc[CANON_AXES];
    double jerk[CANON_AXES];
} canon_axis_limits_t;

/* Limits of one move along its path parameter. */
typedef struct canon_path_limits {
    double vel;     /* largest path speed no axis exceeds its MAX_VELOCITY at */
    double acc;     /* likewise for MAX_ACCELERATION */
    double jerk;    /* likewise for MAX_JERK; 0 when a moving axis has no jerk limit */
    double length;  /* path length used for the ratios (XYZ, else ABC, else UVW) */
} canon_path_limits_t;

/* Straight move by delta[9] (machine units): each moving axis i limits the path value to
 * limit_i * length / |delta_i|, where length is the XYZ length, or the ABC length when XYZ
 * does not move, or the UVW length.  A move of length 0 gets the smallest limit of all axes. */
void canon_line_limits(const double delta[CANON_AXES], const canon_axis_limits_t *lim,
                       canon_path_limits_t *out);

/* Arc in the plane of axes p1/p2 (indexes) with in-plane length arc_len; the other axes move
 * by delta[] as for a line (the helix axis included).  Both plane axes take part over the
 * whole arc, so the smaller plane-axis limit applies to the in-plane share of the path. */
void canon_arc_limits(int p1, int p2, double arc_len, const double delta[CANON_AXES],
                      const canon_axis_limits_t *lim, canon_path_limits_t *out);

#ifdef __cplusplus
}
#endif

#endif
