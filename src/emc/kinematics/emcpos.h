/* emcpos.h: the world pose kinematics and motion exchange (LinuxCNC field names). */
#ifndef EMCPOS_H
#define EMCPOS_H

/* A cartesian point or vector in machine units. */
typedef struct {
    double x, y, z;
} PmCartesian;

/* Nine-axis world position: XYZ, rotary ABC (degrees), linear UVW. */
typedef struct {
    PmCartesian tran;
    double a, b, c;
    double u, v, w;
} EmcPose;

#endif
