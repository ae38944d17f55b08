/* motmod.c: the motion controller module: parameters, load order, threads, functions, shared memory. */
#include <errno.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>
#include "rtapi.h"
#include "rtapi_app.h"
#include "mot_priv.h"
#include "mot_params.h"
#include "mot_link.h"
#include "mot_control.h"

MODULE_LICENSE("GPL");
MODULE_AUTHOR("OpenEMC");
MODULE_DESCRIPTION("Motion controller: command ring, servo loop, joints, axes, spindles");

static int base_period_nsec = 0;
RTAPI_MP_INT(base_period_nsec, "fastest thread period (ns), 0 = no base-thread");
static int servo_period_nsec = 1000000;
RTAPI_MP_INT(servo_period_nsec, "servo thread period (ns)");
static int traj_period_nsec = 0;
RTAPI_MP_INT(traj_period_nsec, "trajectory planner period (ns), 0 = servo period");
static int base_thread_fp = 0;
RTAPI_MP_INT(base_thread_fp, "base-thread uses floating point");
static int num_joints = EMCMOT_MAX_JOINTS;
RTAPI_MP_INT(num_joints, "number of joints (1..16)");
static int num_extrajoints = 0;
RTAPI_MP_INT(num_extrajoints, "number of extra joints (the last ones, not in kinematics)");
static int num_spindles = 1;
RTAPI_MP_INT(num_spindles, "number of spindles (0..8)");
static int num_dio = -1;
RTAPI_MP_INT(num_dio, "number of digital inputs/outputs (1..64, default 4)");
static int num_aio = -1;
RTAPI_MP_INT(num_aio, "number of analog inputs/outputs (1..64, default 4)");
static int num_misc_error = -1;
RTAPI_MP_INT(num_misc_error, "number of misc error inputs (0..64, default 0)");
static char *names_din = "";
RTAPI_MP_STRING(names_din, "names of digital inputs (comma list)");
static char *names_dout = "";
RTAPI_MP_STRING(names_dout, "names of digital outputs");
static char *names_ain = "";
RTAPI_MP_STRING(names_ain, "names of analog inputs");
static char *names_aout = "";
RTAPI_MP_STRING(names_aout, "names of analog outputs");
static char *names_misc_errors = "";
RTAPI_MP_STRING(names_misc_errors, "names of misc error inputs");
static int unlock_joints_mask = 0;
RTAPI_MP_INT(unlock_joints_mask, "joints with unlock/is-unlocked pins (bit per joint)");
static int key = EMCMOT_SHM_DEFAULT_KEY;
RTAPI_MP_INT(key, "motion shared memory key ([EMCMOT]SHMEM_KEY)");

static mot_t mot_storage;
mot_t *mot;
static mot_config_t config;
static int created_base_thread, created_servo_thread;

/* Create base-thread (if any) then servo-thread, fastest first. */
static int create_threads(void)
{
    int rc;

    if (config.base_period_ns > 0) {
        rc = hal_create_thread("base-thread", config.base_period_ns, config.base_thread_fp);
        if (rc < 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: failed to create %ld nsec base thread\n",
                            config.base_period_ns);
            return rc;
        }
        created_base_thread = 1;
    }
    rc = hal_create_thread("servo-thread", config.servo_period_ns, 1);
    if (rc < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: failed to create %ld nsec servo thread\n",
                        config.servo_period_ns);
        return rc;
    }
    created_servo_thread = 1;
    return 0;
}

/* Non-zero when another live process (e.g. motion-logger) owns the segment. */
static int owned_elsewhere(const emcmot_shm_t *shm)
{
    const emcmot_shm_header_t *h = &shm->header;
    int pid = h->owner_pid;

    if (h->magic != EMCMOT_SHM_MAGIC || h->owner_state != EMCMOT_OWNER_RUNNING)
        return 0;
    if (pid <= 0 || pid == (int)getpid())
        return 0;
    return kill(pid, 0) == 0 || errno != ESRCH;
}

/* Create (or take over a retired) motion segment and initialise it as its owner. */
static int open_shm(void)
{
    void *mem;
    int id = rtapi_shmem_new(config.shm_key, mot->comp_id, sizeof(emcmot_shm_t));

    if (id < 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: cannot create motion shared memory (key %d): "
                        "%s; a stale segment of another size may exist\n", config.shm_key,
                        strerror(-id));
        return id;
    }
    mot->shm_id = id;
    rtapi_shmem_getptr(id, &mem);
    if (owned_elsewhere(mem)) {
        const emcmot_shm_header_t *h = mem;
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: motion shared memory (key %d) is in use by %s "
                        "(pid %d)\n", config.shm_key, h->owner_name, (int)h->owner_pid);
        rtapi_shmem_delete(id, mot->comp_id);
        return -EBUSY;
    }
    mot->shm = mem;
    emcmot_shm_init(mot->shm, "motmod", (int)getpid());
    return 0;
}

/* The two servo functions, in the order HAL files add them. */
static int export_functions(void)
{
    int rc = hal_export_funct("motion-command-handler", mot_command_handler, NULL, 1, 0,
                              mot->comp_id);
    if (rc == 0)
        rc = hal_export_funct("motion-controller", mot_controller, NULL, 1, 0, mot->comp_id);
    if (rc < 0)
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: cannot export the motion functions\n");
    return rc;
}

/* Copy the checked parameters into the controller. */
static void apply_config(void)
{
    mot->max_joints = config.num_joints;
    mot->num_joints = config.num_joints;
    mot->num_extra_joints = config.num_extrajoints;
    mot->num_kins_joints = config.num_joints - config.num_extrajoints;
    mot->max_spindles = config.num_spindles;
    mot->num_spindles = config.num_spindles;
    mot->num_dio = config.num_dio;
    mot->num_aio = config.num_aio;
    mot->num_misc_error = config.num_misc_error;
    mot->unlock_joints_mask = config.unlock_joints_mask;
    mot->servo_period = config.servo_period_ns * 1e-9;
    mot->traj_period = config.traj_period_ns * 1e-9;
    mot->interp_rate = (int)((config.traj_period_ns + config.servo_period_ns / 2) /
                             config.servo_period_ns);
}

/* Extra joints need kinematics that can tell where the kinematic joints are. */
static int check_extra_joints(void)
{
    if (mot->num_extra_joints > 0 && mot->kins->type() != KINEMATICS_BOTH) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: nonzero num_extrajoints requires KINEMATICS_BOTH\n");
        return -EINVAL;
    }
    return 0;
}

/* Undo what a failed load or an unload set up. */
static void teardown(void)
{
    if (mot->shm) {
        emcmot_shm_retire(mot->shm);
        rtapi_shmem_delete(mot->shm_id, mot->comp_id);
        mot->shm = NULL;
    }
    mot_unlink();
    if (created_servo_thread)
        hal_thread_delete("servo-thread");
    if (created_base_thread)
        hal_thread_delete("base-thread");
    created_servo_thread = created_base_thread = 0;
    if (mot->comp_id > 0)
        hal_exit(mot->comp_id);
    mot->comp_id = 0;
}

/* Load: parameters, links, shared memory, threads, pins, homing, functions. */
int rtapi_app_main(void)
{
    mot_raw_params_t raw = {
        base_period_nsec, servo_period_nsec, traj_period_nsec, base_thread_fp,
        num_joints, num_extrajoints, num_spindles, num_dio, num_aio, num_misc_error,
        names_din, names_dout, names_ain, names_aout, names_misc_errors,
        unlock_joints_mask, key,
    };
    int rc;

    mot = &mot_storage;
    memset(mot, 0, sizeof *mot);
    if (mot_params_check(&raw, &config) < 0)
        return -EINVAL;
    apply_config();
    rc = mot_link_kins();
    if (rc == 0)
        rc = check_extra_joints();
    if (rc == 0)
        rc = mot_link_tp();
    if (rc == 0)
        rc = mot_link_home();
    if (rc < 0) {
        mot_unlink();
        return rc;
    }
    mot->comp_id = hal_init("motmod");
    if (mot->comp_id < 0) {
        rc = mot->comp_id;
        mot->comp_id = 0;
        mot_unlink();
        return rc;
    }
    rc = open_shm();
    if (rc == 0)
        rc = mot_pins_create(&config);
    if (rc == 0)
        rc = mot_init_state();
    if (rc == 0)
        rc = create_threads();
    if (rc == 0)
        rc = export_functions();
    if (rc < 0) {
        teardown();
        return rc;
    }
    hal_ready(mot->comp_id);
    return 0;
}

/* Unload: the segment is marked gone for task, the planner released. */
void rtapi_app_exit(void)
{
    teardown();
}
