/* mot_params.h: motmod's module parameters, checked at load (motion.md sec. 1). */
#ifndef MOT_PARAMS_H
#define MOT_PARAMS_H

#include "hal.h"

#define MOT_NAME_MAX 40     /* characters of one names_*= entry */

/* One names_*= list. */
typedef struct mot_names {
    int count;
    char name[64][MOT_NAME_MAX + 1];
} mot_names_t;

/* The parameters after checking (counts resolved from names). */
typedef struct mot_config {
    long base_period_ns, servo_period_ns, traj_period_ns;
    int base_thread_fp;
    int num_joints, num_extrajoints, num_spindles;
    int num_dio, num_aio, num_misc_error;
    unsigned unlock_joints_mask;
    int shm_key;
    mot_names_t din, dout, ain, aout, misc;
} mot_config_t;

/* Raw values as halcmd set them. */
typedef struct mot_raw_params {
    int base_period_nsec, servo_period_nsec, traj_period_nsec, base_thread_fp;
    int num_joints, num_extrajoints, num_spindles, num_dio, num_aio, num_misc_error;
    const char *names_din, *names_dout, *names_ain, *names_aout, *names_misc_errors;
    int unlock_joints_mask, key;
} mot_raw_params_t;

/* Check every parameter; 0, or -EINVAL after printing the MOTION: error. */
int mot_params_check(const mot_raw_params_t *raw, mot_config_t *cfg);

#endif
