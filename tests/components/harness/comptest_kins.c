/* comptest_kins.c: comptest commands that call a loaded kinematics module's exported functions. */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emc/kinematics/kins_ops.h"
#include "emc/kinematics/kins_coords.h"

/* The module's kins_ops table, checked, or NULL after printing why. */
static const kins_ops_t *kins_table(void *module)
{
    char why[200];
    const kins_ops_t *ops = module ? dlsym(module, "kins_ops") : NULL;
    if (kins_ops_check(ops, why, sizeof(why)) < 0) {
        printf("kins_ops: %s\n", why);
        return NULL;
    }
    return ops;
}

/* The pose kfwd passes in (iterative kinematics start from it); kguess sets it, 0 by default. */
static EmcPose kfwd_guess;

/* The inverse flags (arm configuration) kinv passes in; kflags sets them, 0 by default. */
static KINEMATICS_INVERSE_FLAGS kinv_flags;
/* The joints kinv starts from (a kinematics may keep one at a singularity); kseed sets them. */
static double kinv_seed[KINS_MAX_JOINTS];

/* kflags N: the inverse flags given to the following kinv calls. */
static void cmd_kflags(int argc, char **argv)
{
    kinv_flags = argc > 1 ? strtoul(argv[1], NULL, 0) : 0;
}

/* kseed J0 J1 ...: the joints the following kinv calls start from (others 0). */
static void cmd_kseed(int argc, char **argv)
{
    memset(kinv_seed, 0, sizeof(kinv_seed));
    for (int i = 1; i < argc && i <= KINS_MAX_JOINTS; i++)
        kinv_seed[i - 1] = strtod(argv[i], NULL);
}

/* kguess X Y Z A B C U V W: the pose given to the following kfwd calls. */
static void cmd_kguess(int argc, char **argv)
{
    memset(&kfwd_guess, 0, sizeof(kfwd_guess));
    for (int a = 0; a < KINS_AXES && a + 1 < argc; a++)
        kins_pose_set(&kfwd_guess, a, strtod(argv[a + 1], NULL));
}

/* kfwd J0 J1 ...: forward kinematics from the given joints (others 0); prints rc and the pose. */
static void cmd_kfwd(const kins_ops_t *ops, int argc, char **argv)
{
    double joints[KINS_MAX_JOINTS] = {0};
    EmcPose pos = kfwd_guess;
    KINEMATICS_FORWARD_FLAGS ff = 0;
    KINEMATICS_INVERSE_FLAGS fi = 0;
    for (int i = 1; i < argc && i <= KINS_MAX_JOINTS; i++)
        joints[i - 1] = strtod(argv[i], NULL);
    int rc = ops->forward(joints, &pos, &ff, &fi);
    printf("fwd %d:", rc);
    for (int a = 0; a < KINS_AXES; a++)
        printf(" %c=%.6f", kins_axis_letter(a), kins_pose_get(&pos, a));
    if (fi)
        printf(" iflags=%lu", fi);
    printf("\n");
}

/* kinv N X Y Z A B C U V W: inverse kinematics; prints rc and the first N joints. */
static void cmd_kinv(const kins_ops_t *ops, int argc, char **argv)
{
    double joints[KINS_MAX_JOINTS];
    EmcPose pos;
    KINEMATICS_FORWARD_FLAGS ff = 0;
    KINEMATICS_INVERSE_FLAGS fi = kinv_flags;
    memcpy(joints, kinv_seed, sizeof(joints));
    memset(&pos, 0, sizeof(pos));
    int n = argc > 1 ? atoi(argv[1]) : 0;
    if (n < 0 || n > KINS_MAX_JOINTS)
        n = KINS_MAX_JOINTS;
    for (int a = 0; a < KINS_AXES && a + 2 < argc; a++)
        kins_pose_set(&pos, a, strtod(argv[a + 2], NULL));
    int rc = ops->inverse(&pos, joints, &fi, &ff);
    printf("inv %d:", rc);
    for (int j = 0; j < n; j++)
        printf(" j%d=%.6f", j, joints[j]);
    if (ff)
        printf(" fflags=%lu", ff);
    printf("\n");
}

/* Handle a kinematics command; 1 when argv[0] was one. */
int comptest_kins_dispatch(void *module, int argc, char **argv)
{
    const char *c = argv[0];
    if (!strcmp(c, "kguess") || !strcmp(c, "kflags") || !strcmp(c, "kseed")) {
        if (!strcmp(c, "kguess"))
            cmd_kguess(argc, argv);
        else if (!strcmp(c, "kflags"))
            cmd_kflags(argc, argv);
        else
            cmd_kseed(argc, argv);
        return 1;
    }
    if (strcmp(c, "kfwd") && strcmp(c, "kinv") && strcmp(c, "ktype") && strcmp(c, "kswitch"))
        return 0;
    const kins_ops_t *ops = kins_table(module);
    if (!ops)
        return 1;
    if (!strcmp(c, "kfwd"))
        cmd_kfwd(ops, argc, argv);
    else if (!strcmp(c, "kinv"))
        cmd_kinv(ops, argc, argv);
    else if (!strcmp(c, "ktype"))
        printf("type %d switchable %d\n", (int)ops->type(), ops->switchable());
    else
        printf("switch %d -> %d, type %d\n", argc > 1 ? atoi(argv[1]) : 0,
               ops->switch_type(argc > 1 ? atoi(argv[1]) : 0), (int)ops->type());
    return 1;
}
