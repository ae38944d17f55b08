/* tp_vec.h: nine-axis vectors (X Y Z A B C U V W) and the length metric of a move. */
#ifndef TP_VEC_H
#define TP_VEC_H

#include <math.h>
#include "emcpos.h"

#define TP_NAX 9

/* Axis indexes in EmcPose order. */
enum { TP_AX_X, TP_AX_Y, TP_AX_Z, TP_AX_A, TP_AX_B, TP_AX_C, TP_AX_U, TP_AX_V, TP_AX_W };

/* Which axes measure the length of a move (LinuxCNC: XYZ if they move, else UVW, else ABC). */
typedef enum tp_metric {
    TP_METRIC_XYZ = 0,
    TP_METRIC_UVW = 1,
    TP_METRIC_ABC = 2
} tp_metric_t;

typedef struct tp_vec {
    double x[TP_NAX];
} tp_vec_t;

/* EmcPose to vector. */
static inline tp_vec_t tp_vec_from_pose(const EmcPose *p)
{
    tp_vec_t v = {{p->tran.x, p->tran.y, p->tran.z, p->a, p->b, p->c, p->u, p->v, p->w}};
    return v;
}

/* Vector to EmcPose. */
static inline EmcPose tp_vec_to_pose(const tp_vec_t *v)
{
    EmcPose p = {{v->x[0], v->x[1], v->x[2]}, v->x[3], v->x[4], v->x[5], v->x[6], v->x[7], v->x[8]};
    return p;
}

/* a - b. */
static inline tp_vec_t tp_vec_sub(const tp_vec_t *a, const tp_vec_t *b)
{
    tp_vec_t r;
    for (int i = 0; i < TP_NAX; i++)
        r.x[i] = a->x[i] - b->x[i];
    return r;
}

/* a + k b. */
static inline tp_vec_t tp_vec_axpy(const tp_vec_t *a, double k, const tp_vec_t *b)
{
    tp_vec_t r;
    for (int i = 0; i < TP_NAX; i++)
        r.x[i] = a->x[i] + k * b->x[i];
    return r;
}

/* k a. */
static inline tp_vec_t tp_vec_scale(const tp_vec_t *a, double k)
{
    tp_vec_t r;
    for (int i = 0; i < TP_NAX; i++)
        r.x[i] = k * a->x[i];
    return r;
}

/* Dot product over all nine axes. */
static inline double tp_vec_dot(const tp_vec_t *a, const tp_vec_t *b)
{
    double s = 0.0;
    for (int i = 0; i < TP_NAX; i++)
        s += a->x[i] * b->x[i];
    return s;
}

/* Euclidean norm of the three axes starting at first. */
static inline double tp_vec_norm3(const tp_vec_t *a, int first)
{
    return sqrt(a->x[first] * a->x[first] + a->x[first + 1] * a->x[first + 1] +
                a->x[first + 2] * a->x[first + 2]);
}

/* First axis of the group a metric measures. */
static inline int tp_metric_first(tp_metric_t m)
{
    return m == TP_METRIC_XYZ ? TP_AX_X : m == TP_METRIC_UVW ? TP_AX_U : TP_AX_A;
}

/* Length of a displacement in a metric. */
static inline double tp_vec_metric_norm(const tp_vec_t *a, tp_metric_t m)
{
    return tp_vec_norm3(a, tp_metric_first(m));
}

/* Largest of the XYZ, UVW and ABC group norms (deviation from the path). */
static inline double tp_vec_dev_norm(const tp_vec_t *a)
{
    double n = tp_vec_norm3(a, TP_AX_X);
    double u = tp_vec_norm3(a, TP_AX_U);
    double r = tp_vec_norm3(a, TP_AX_A);
    return fmax(n, fmax(u, r));
}

/* Largest absolute component. */
static inline double tp_vec_maxabs(const tp_vec_t *a)
{
    double m = 0.0;
    for (int i = 0; i < TP_NAX; i++)
        m = fmax(m, fabs(a->x[i]));
    return m;
}

/* All components finite. */
static inline int tp_vec_finite(const tp_vec_t *a)
{
    for (int i = 0; i < TP_NAX; i++)
        if (!isfinite(a->x[i]))
            return 0;
    return 1;
}

#endif
