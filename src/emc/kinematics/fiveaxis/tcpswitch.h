/* tcpswitch.h: frame of the 2.9-style TCP kinematics (type 0 identity, type 1 tool center point). */
#ifndef FIVEAXIS_TCPSWITCH_H
#define FIVEAXIS_TCPSWITCH_H

/* What a module supplies; tcpswitch.c provides the entry points and the exports. */
typedef struct tcpswitch_def {
    const char *name;      /* HAL component name, e.g. "xyzab_tdr_kins" */
    const char *prefix;    /* pin prefix, e.g. "xyzab-tdr-kins" */
    const char *axes;      /* axis letter of each joint, in joint order, e.g. "XYZAB" */
    /* Make the module's pins; 0 or negative errno. */
    int (*setup)(int comp_id, const char *prefix);
    /* TCP kinematics on arrays in joint order (world[i] is the axis of joint i). */
    int (*tcp_forward)(const double *joints, double *world);
    int (*tcp_inverse)(const double *world, double *joints);
} tcpswitch_def_t;

/* Each module defines exactly one of these. */
extern const tcpswitch_def_t tcpswitch_def;

#endif
