/* mot_params.c: check motmod's module parameters and split the names_*= lists. */
#include <stdarg.h>
#include <string.h>
#include "rtapi.h"
#include "mot_params.h"
#include "motion_cmd.h"

#define PARAM_UNSET (-1)

/* Print one MOTION: error and return -EINVAL. */
static int param_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int param_error(const char *fmt, ...)
{
    char text[256];
    va_list ap;

    va_start(ap, fmt);
    rtapi_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    rtapi_print_msg(RTAPI_MSG_ERR, "MOTION: %s\n", text);
    return -EINVAL;
}

/* Check value against lo..hi with LinuxCNC's wording. */
static int check_range(const char *what, int value, int lo, int hi)
{
    if (value < lo || value > hi)
        return param_error("%s is %d, must be between %d and %d", what, value, lo, hi);
    return 0;
}

/* Split a comma list into out; blank entries and over-long names are refused. */
static int split_names(const char *list, mot_names_t *out, const char *param)
{
    const char *p = list;

    out->count = 0;
    if (!list || !*list)
        return 0;
    for (;;) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == 0)
            return param_error("%s='%s': empty name", param, list);
        if (len > MOT_NAME_MAX)
            return param_error("%s: name '%.*s' is longer than %d characters", param, (int)len, p,
                               MOT_NAME_MAX);
        if (out->count >= 64)
            return param_error("%s: more than 64 names", param);
        memcpy(out->name[out->count], p, len);
        out->name[out->count][len] = '\0';
        out->count++;
        if (!end)
            return 0;
        p = end + 1;
    }
}

/* A count from names or from num_* (not both); default when neither is given. */
static int resolve_count(int num, int named, int dflt, const char *kind, int *out)
{
    if (num != PARAM_UNSET && named > 0)
        return param_error("Can't specify both names and number for %s pins", kind);
    *out = named > 0 ? named : (num == PARAM_UNSET ? dflt : num);
    return 0;
}

/* Periods: positive servo period; base thread only when 0 < base < servo. */
static int check_periods(const mot_raw_params_t *raw, mot_config_t *cfg)
{
    if (raw->servo_period_nsec <= 0)
        return param_error("servo_period_nsec is %d, must be > 0", raw->servo_period_nsec);
    if (raw->base_period_nsec < 0)
        return param_error("base_period_nsec is %d, must be >= 0", raw->base_period_nsec);
    if (raw->traj_period_nsec < 0)
        return param_error("traj_period_nsec is %d, must be >= 0", raw->traj_period_nsec);
    cfg->base_period_ns = raw->base_period_nsec;
    cfg->servo_period_ns = raw->servo_period_nsec;
    if (cfg->base_period_ns > 0 && cfg->base_period_ns < cfg->servo_period_ns) {
        long n = (cfg->servo_period_ns + cfg->base_period_ns / 2) / cfg->base_period_ns;
        cfg->servo_period_ns = n * cfg->base_period_ns;
    } else {
        cfg->base_period_ns = 0;
    }
    cfg->traj_period_ns = raw->traj_period_nsec > 0 ? raw->traj_period_nsec : cfg->servo_period_ns;
    if (cfg->traj_period_ns < cfg->servo_period_ns)
        cfg->traj_period_ns = cfg->servo_period_ns;
    cfg->base_thread_fp = raw->base_thread_fp;
    return 0;
}

/* Joint, spindle and I/O counts. */
static int check_counts(const mot_raw_params_t *raw, mot_config_t *cfg)
{
    int n = 0;

    n |= check_range("num_joints", raw->num_joints, 1, EMCMOT_MAX_JOINTS);
    if (n == 0)
        n |= check_range("num_extrajoints", raw->num_extrajoints, 0, raw->num_joints);
    n |= check_range("num_spindles", raw->num_spindles, 0, EMCMOT_MAX_SPINDLES);
    if (n)
        return -EINVAL;
    cfg->num_joints = raw->num_joints;
    cfg->num_extrajoints = raw->num_extrajoints;
    cfg->num_spindles = raw->num_spindles;
    if (resolve_count(raw->num_dio, cfg->din.count > cfg->dout.count ? cfg->din.count : cfg->dout.count,
                      4, "digital", &cfg->num_dio) < 0 ||
        resolve_count(raw->num_aio, cfg->ain.count > cfg->aout.count ? cfg->ain.count : cfg->aout.count,
                      4, "analog", &cfg->num_aio) < 0 ||
        resolve_count(raw->num_misc_error, cfg->misc.count, 0, "misc error", &cfg->num_misc_error) < 0)
        return -EINVAL;
    n |= check_range("num_dio", cfg->num_dio, 1, EMCMOT_MAX_DIO);
    n |= check_range("num_aio", cfg->num_aio, 1, EMCMOT_MAX_AIO);
    n |= check_range("num_misc_error", cfg->num_misc_error, 0, EMCMOT_MAX_MISC_ERROR);
    return n ? -EINVAL : 0;
}

/* Check every parameter. */
int mot_params_check(const mot_raw_params_t *raw, mot_config_t *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    if (check_periods(raw, cfg) < 0)
        return -EINVAL;
    if (split_names(raw->names_din, &cfg->din, "names_din") < 0 ||
        split_names(raw->names_dout, &cfg->dout, "names_dout") < 0 ||
        split_names(raw->names_ain, &cfg->ain, "names_ain") < 0 ||
        split_names(raw->names_aout, &cfg->aout, "names_aout") < 0 ||
        split_names(raw->names_misc_errors, &cfg->misc, "names_misc_errors") < 0)
        return -EINVAL;
    if (check_counts(raw, cfg) < 0)
        return -EINVAL;
    if (raw->unlock_joints_mask < 0 || raw->unlock_joints_mask >= (1 << EMCMOT_MAX_JOINTS))
        return param_error("unlock_joints_mask is 0x%x, must be 0..0x%x",
                           (unsigned)raw->unlock_joints_mask, (1u << EMCMOT_MAX_JOINTS) - 1);
    cfg->unlock_joints_mask = (unsigned)raw->unlock_joints_mask;
    if (raw->key <= 0)
        return param_error("key is %d, must be > 0", raw->key);
    cfg->shm_key = raw->key;
    return 0;
}
