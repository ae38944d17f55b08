/* mot_link.c: find and check the kinematics, planner and homing tables loaded before motmod. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_link.h"

#define MAX_HELD 3

static void *held[MAX_HELD];    /* extra references on the modules motmod calls into */
static int num_held;

/* An exported symbol of any module loaded so far (rtapi_app loads them RTLD_GLOBAL);
 * its module gets an extra reference so unloading it cannot unmap code motmod calls. */
static const void *module_symbol(const char *name)
{
    const void *sym = dlsym(RTLD_DEFAULT, name);
    Dl_info info;

    if (sym && num_held < MAX_HELD && dladdr(sym, &info) && info.dli_fname) {
        void *h = dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD);
        if (h)
            held[num_held++] = h;
    }
    return sym;
}

/* The kinematics module's kins_ops; refused when missing or of another version. */
int mot_link_kins(void)
{
    const kins_ops_t *ops = module_symbol("kins_ops");
    char why[200];

    if (!ops) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: no kinematics module is loaded: "
                        "loadrt a kinematics module ([KINS]KINEMATICS) before motmod\n");
        return -ENOENT;
    }
    if (kins_ops_check(ops, why, sizeof why) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: kinematics refused: %s\n", why);
        return -EPROTO;
    }
    mot->kins = ops;
    return 0;
}

/* The planner module's tp_ops and one planner of MOT_TP_QUEUE_SIZE segments. */
int mot_link_tp(void)
{
    const tp_ops_t *ops = module_symbol("tp_ops");
    char why[200];

    if (!ops) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: no trajectory planner is loaded: "
                        "loadrt tpmod ([TRAJ]TPMOD) before motmod\n");
        return -ENOENT;
    }
    if (tp_ops_check(ops, why, sizeof why) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: trajectory planner refused: %s\n", why);
        return -EPROTO;
    }
    mot->tp = ops->create(MOT_TP_QUEUE_SIZE);
    if (!mot->tp) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: %s could not create a planner of %d segments\n",
                        ops->name, MOT_TP_QUEUE_SIZE);
        return -ENOMEM;
    }
    mot->tp_ops = ops;
    return 0;
}

/* The homing module's home_ops. */
int mot_link_home(void)
{
    const home_ops_t *ops = module_symbol("home_ops");
    char why[200];

    if (!ops) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: no homing module is loaded: "
                        "loadrt homemod ([EMCMOT]HOMEMOD) before motmod\n");
        return -ENOENT;
    }
    if (home_ops_check(ops, why, sizeof why) < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: homing module refused: %s\n", why);
        return -EPROTO;
    }
    mot->home = ops;
    return 0;
}

/* Give the planner back. */
void mot_unlink(void)
{
    if (mot->tp_ops && mot->tp)
        mot->tp_ops->destroy(mot->tp);
    mot->tp = NULL;
    while (num_held > 0)
        dlclose(held[--num_held]);
}
