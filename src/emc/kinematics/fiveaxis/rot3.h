/* rot3.h: small 3x3 rotation helpers shared by the pure kinematics math files. */
#ifndef FIVEAXIS_ROT3_H
#define FIVEAXIS_ROT3_H

/* A rotation matrix, row major. */
typedef struct {
    double m[3][3];
} rot3_t;

/* Rotation by angle_deg about a unit axis vector (right-hand rule). */
rot3_t rot3_about(const double axis[3], double angle_deg);
/* Rotation by angle_deg about machine axis 0 X, 1 Y or 2 Z. */
rot3_t rot3_principal(int axis, double angle_deg);
/* Product a * b. */
rot3_t rot3_mul(const rot3_t *a, const rot3_t *b);
/* out = r * v (out may alias v). */
void rot3_apply(const rot3_t *r, const double v[3], double out[3]);
/* out = transpose(r) * v, the inverse rotation (out may alias v). */
void rot3_apply_inv(const rot3_t *r, const double v[3], double out[3]);
/* 1 when all n values are finite numbers. */
int rot3_all_finite(const double *v, int n);

#endif
