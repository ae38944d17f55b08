/* rotary_math.h: pure tool-center-point math of the 5/6-axis kinematics (no HAL, angles in degrees). */
#ifndef FIVEAXIS_ROTARY_MATH_H
#define FIVEAXIS_ROTARY_MATH_H

#ifdef __cplusplus
extern "C" {
#endif

/* Machine axis a rotary turns about. */
enum { ROT_X = 0, ROT_Y = 1, ROT_Z = 2 };

/* Two rotaries in the table: the secondary sits on the primary (trt, tdr machines). */
typedef struct {
    int primary_axis;        /* ROT_X (A) or ROT_Y (B): the tilting axis fixed to the bed */
    int secondary_axis;      /* ROT_Y (B) or ROT_Z (C): the rotary carried by the primary */
    double rot_point[3];     /* a point of the secondary axis (x/y/z-rot-point) */
    double offset[3];        /* primary axis passes through rot_point + offset (x/y/z-offset) */
    double tool_offset;      /* tool length along Z (tool-offset) */
    int conventional;        /* conventional-directions: both rotaries turn the other way */
} table2_geom_t;

/* World XYZ (table frame) and rotary angles -> XYZ joints; 0, or -1 when not finite. */
int table2_inverse(const table2_geom_t *g, const double world[3], double primary_deg,
                   double secondary_deg, double joints[3]);
/* XYZ joints and rotary angles -> world XYZ; 0, or -1 when not finite. */
int table2_forward(const table2_geom_t *g, const double joints[3], double primary_deg,
                   double secondary_deg, double world[3]);
/* 5axiskins: XYZ joints, B, C, W and pivot length -> world XYZ; 0, or -1 when not finite. */
int pivot5_forward(double pivot_length, const double joints[3], double b_deg, double c_deg,
                   double w, double world[3]);
/* 5axiskins: world XYZ, B, C, W and pivot length -> XYZ joints; 0, or -1 when not finite. */
int pivot5_inverse(double pivot_length, const double world[3], double b_deg, double c_deg,
                   double w, double joints[3]);

/* maxkins: the nine joints XYZABCUVW -> nine world axes; 0, or -1 when not finite. */
int maxkins_forward(double pivot_length, int conventional, const double joints[9], double world[9]);
/* maxkins: the nine world axes XYZABCUVW -> nine joints; 0, or -1 when not finite. */
int maxkins_inverse(double pivot_length, int conventional, const double world[9], double joints[9]);

#ifdef __cplusplus
}
#endif

#endif
