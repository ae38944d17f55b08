/* tp_blend.h: curvature-continuous corner blends (degree-7 G2 Hermite) and their sizing within the tolerance. */
#ifndef TP_BLEND_H
#define TP_BLEND_H

#include "tp_geom.h"

/* Blend shapes: G2 (curvature-continuous, for jerk limits) or G1 (a parabola run at constant
 * parameter speed: a constant acceleration, which may jump at its ends; trapezoid planning). */
typedef enum tp_blend_shape {
    TP_BLEND_G2 = 0,
    TP_BLEND_G1 = 1
} tp_blend_shape_t;

/* A corner between the end of geometry ga and the start of geometry gb. */
typedef struct tp_corner {
    const tp_geo_t *ga;
    const tp_geo_t *gb;
    double theta;               /* angle between the tangents at the corner, rad */
    double kink;                /* |curvature jump| at the corner (tangent joins) */
    tp_blend_shape_t shape;     /* G2 unless the caller asks for G1 */
} tp_corner_t;

/* How a blend is placed: distances cut from each side and curvature overrides at the ends. */
typedef struct tp_blend_spec {
    double da, db;              /* length taken from the end of ga and the start of gb */
    int ka_set, kb_set;         /* use ka/kb instead of the geometry's own curvature */
    tp_vec_t ka, kb;
} tp_blend_spec_t;

/* Tables for line-line corners; filled once by tp_blend_init. */
void tp_blend_init(void);
/* Describe the corner between ga's end and gb's start (shape G2). */
void tp_corner_describe(tp_corner_t *c, const tp_geo_t *ga, const tp_geo_t *gb);
/* Largest symmetric cut d whose blend passes within tol of the corner (line-line estimate). */
double tp_blend_tol_cut(const tp_corner_t *c, double tol);
/* Smallest symmetric cut whose blend allows speed v with normal acceleration acc and jerk jerk (0 = none). */
double tp_blend_need_cut(const tp_corner_t *c, double v, double acc, double jerk);
/* Speed a symmetric blend of cut d allows (the inverse of tp_blend_need_cut) and its length. */
double tp_blend_speed_at_cut(const tp_corner_t *c, double d, double acc, double jerk, double *len);
/* Build the blend; 0, or -1 when the geometry is degenerate. */
int tp_blend_build(tp_geo_t *out, const tp_corner_t *c, const tp_blend_spec_t *spec);
/* Distance from the corner point to the blend, and largest distance from the blend to the path. */
void tp_blend_deviation(const tp_geo_t *blend, const tp_corner_t *c, const tp_blend_spec_t *spec,
                        double *vertex_miss, double *path_dev);
/* The larger of the vertex miss and the path deviation (cheaper where the geometry allows). */
double tp_blend_worst(const tp_geo_t *blend, const tp_corner_t *c, const tp_blend_spec_t *spec, double tol);

#endif
