/* tp_geom.h: path geometry: lines, arcs (helix, spiral, extra axes) and degree-7 (septic) blends, parameterised by length. */
#ifndef TP_GEOM_H
#define TP_GEOM_H

#include "tp_vec.h"

/* Pseudo-axis index of the path itself (the length metric) in derivative bounds. */
#define TP_PATH_AX TP_NAX
#define TP_NBOUND (TP_NAX + 1)

typedef enum tp_geo_kind {
    TP_GEO_LINE = 0,
    TP_GEO_ARC = 1,
    TP_GEO_SEPTIC = 2
} tp_geo_kind_t;

/* Straight move: p(s) = start + dir s, s in [0, len]. */
typedef struct tp_line {
    tp_vec_t start, end, dir;
} tp_line_t;

/* Circle, helix or spiral in XYZ; A B C U V W move linearly with the angle. */
typedef struct tp_arc {
    tp_vec_t start, end;
    double c[3];                /* centre */
    double e1[3], e2[3];        /* plane basis: e1 towards the start, e2 = normal x e1 */
    double n[3];                /* unit normal (counter-clockwise about it) */
    double r0, r1;              /* radius at start and end */
    double sweep;               /* angle swept, > 0 */
    double h;                   /* displacement along the normal */
} tp_arc_t;

#define TP_BEZ_DEG 7               /* degree of the blend polynomials */

/* Degree-7 (septic) Bezier blend: u = s / len in [0, 1]; c holds the same polynomial in powers of u. */
typedef struct tp_septic {
    tp_vec_t b[TP_BEZ_DEG + 1];
    tp_vec_t c[TP_BEZ_DEG + 1];
} tp_septic_t;

typedef struct tp_geo {
    tp_geo_kind_t kind;
    tp_metric_t metric;         /* axes that measure len */
    double len;                 /* length in the metric (for blends: the parameter scale) */
    union {
        tp_line_t line;
        tp_arc_t arc;
        tp_septic_t q;
    } u;
} tp_geo_t;

/* Derivatives with respect to length at a point. */
typedef struct tp_jet {
    tp_vec_t p, d1, d2;
} tp_jet_t;

/* Largest |d1|, |d2|, |d3| per axis over a parameter range; index TP_PATH_AX is the metric norm. */
typedef struct tp_bounds {
    double d1[TP_NBOUND];
    double d2[TP_NBOUND];
    double d3[TP_NBOUND];
    /* 1 where the coordinate runs as a sinusoid of the length (an axis in the plane of a circle or
     * helix, or the path itself): its first and third derivatives peak a quarter period from its
     * second, so in the acceleration and jerk the parts they carry add as a hypot, not a sum */
    unsigned char phase[TP_NBOUND];
} tp_bounds_t;

/* Make a line from start to end; 0, or -1 when it has no length in any metric. */
int tp_geo_line(tp_geo_t *g, const tp_vec_t *start, const tp_vec_t *end);
/* Make an arc; turn < 0 reverses the direction (extra turns -turn-1); 0 or -1 when degenerate. */
int tp_geo_arc(tp_geo_t *g, const tp_vec_t *start, const tp_vec_t *end, const double center[3],
               const double normal[3], int turn);
/* Position at length s (s clamped to [0, len]; the exact end point at len). */
tp_vec_t tp_geo_eval(const tp_geo_t *g, double s);
/* Position, first and second derivative at s. */
tp_jet_t tp_geo_jet(const tp_geo_t *g, double s);
/* Derivative bounds over [s0, s1]. */
void tp_geo_bounds(const tp_geo_t *g, double s0, double s1, tp_bounds_t *b);
/* Length of a septic in metric m (8-point Gauss-Legendre). */
double tp_septic_length(const tp_septic_t *q, tp_metric_t m);
/* Septic G2 Hermite: position, unit-length tangent, curvature vector and third derivative (a3, b3;
 * NULL for zero) at both ends, scale lam. */
void tp_septic_hermite(tp_septic_t *q, const tp_jet_t *a, const tp_jet_t *b, double lam,
                       const tp_vec_t *a3, const tp_vec_t *b3);
/* Point of a septic at u in [0, 1]. */
tp_vec_t tp_septic_point(const tp_septic_t *q, double u);

#endif
