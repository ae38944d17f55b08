/* mot_cmd_traj.c: planner settings, overrides and synced/immediate I/O commands. */
#include "rtapi.h"
#include "mot_cmd.h"

/* Hand the current limits to the planner. */
void mot_tp_limits_changed(void)
{
    tp_limits_t *l = &mot->tp_limits;

    l->cycle_time = mot->traj_period;
    l->vmax = mot->vel;
    l->ini_maxvel = mot->ini_maxvel;
    l->vlimit = mot->vel_limit;
    l->amax = mot->acc;
    l->jmax = mot->jerk;
    l->max_feed_override = mot->max_feed_override;
    l->scurve_peak_scale = mot->scurve_peak_scale;
    for (int a = 0; a < MOT_NUM_AXES; a++) {
        l->axis_vel[a] = mot->axis[a].vel_limit;
        l->axis_acc[a] = mot->axis[a].acc_limit;
        l->axis_jerk[a] = mot->axis[a].jerk_limit;
    }
    mot->tp_ops->set_limits(mot->tp, l);
}

/* A value that must not be negative. */
static int need_nonnegative(const emcmot_command_t *c, double v)
{
    if (v < 0.0)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "%s: %g is negative",
                          emcmot_command_name(c->command), v);
    return EMCMOT_COMMAND_OK;
}

/* FEED_SCALE: feed override (>= 0). */
int mot_cmd_feed_scale(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->scale) != EMCMOT_COMMAND_OK)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->feed_scale = c->scale;
    return EMCMOT_COMMAND_OK;
}

/* RAPID_SCALE: rapid override (>= 0). */
int mot_cmd_rapid_scale(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->scale) != EMCMOT_COMMAND_OK)
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->rapid_scale = c->scale;
    return EMCMOT_COMMAND_OK;
}

/* FS_ENABLE (M48/M49/M50). */
int mot_cmd_fs_enable(const emcmot_command_t *c)
{
    mot->fs_enabled = c->enable != 0;
    return EMCMOT_COMMAND_OK;
}

/* FH_ENABLE (M53). */
int mot_cmd_fh_enable(const emcmot_command_t *c)
{
    mot->fh_enabled = c->enable != 0;
    return EMCMOT_COMMAND_OK;
}

/* AF_ENABLE (M52). */
int mot_cmd_af_enable(const emcmot_command_t *c)
{
    mot->af_enabled = c->enable != 0;
    return EMCMOT_COMMAND_OK;
}

/* SET_VEL: default velocity and its ceiling. */
int mot_cmd_set_vel(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->vel) || need_nonnegative(c, c->ini_maxvel))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->vel = c->vel;
    mot->ini_maxvel = c->ini_maxvel;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_VEL_LIMIT: [TRAJ]MAX_LINEAR_VELOCITY. */
int mot_cmd_set_vel_limit(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->vel))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->vel_limit = c->vel;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_ACC: [TRAJ]DEFAULT_LINEAR_ACCELERATION (also caps joint-mode accelerations). */
int mot_cmd_set_acc(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->acc))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->acc = c->acc;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_JERK: [TRAJ]MAX_LINEAR_JERK. */
int mot_cmd_set_jerk(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->jerk))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->jerk = c->jerk;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_PLANNER_TYPE: 0 trapezoid, 1 S-curve; deferred while motion is queued. */
int mot_cmd_set_planner_type(const emcmot_command_t *c)
{
    tp_result_t r;

    if (c->planner_type != TP_PLANNER_TRAPEZOID && c->planner_type != TP_PLANNER_SCURVE)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "planner type %d is not 0 or 1",
                          c->planner_type);
    if (!mot->tp_ops->is_done(mot->tp)) {
        mot->planner_type_pending = c->planner_type;
        mot_report("planner switch deferred until queued motion completes (requested type %d)",
                   c->planner_type);
        return EMCMOT_COMMAND_OK;
    }
    r = mot->tp_ops->set_planner_type(mot->tp, (tp_planner_type_t)c->planner_type);
    if (r == TP_NO_JERK_LIMIT)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "S-curve planner refused: no usable jerk limit - set "
                          "[TRAJ]MAX_LINEAR_JERK and per-axis [AXIS_*]MAX_JERK");
    if (r != TP_OK && r != TP_DEFERRED)
        return mot_refuse(EMCMOT_COMMAND_BAD_EXEC, 1, "planner refused type %d (result %d)",
                          c->planner_type, (int)r);
    mot->planner_type = c->planner_type;
    mot->planner_type_pending = -1;
    return EMCMOT_COMMAND_OK;
}

/* SET_SCURVE_PEAK_SCALE: clamped to 0.1 .. 1.0. */
int mot_cmd_set_scurve_peak_scale(const emcmot_command_t *c)
{
    double s = c->scale;

    mot->scurve_peak_scale = s < 0.1 ? 0.1 : (s > 1.0 ? 1.0 : s);
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_TERM_COND: STOP 0 (G61.1), EXACT 1 (G61), BLEND 2 (G64), for the moves that follow. */
int mot_cmd_set_term_cond(const emcmot_command_t *c)
{
    if (c->term_cond < TP_TERM_COND_STOP || c->term_cond > TP_TERM_COND_BLEND)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "SET_TERM_COND: bad condition %d",
                          c->term_cond);
    if (need_nonnegative(c, c->tolerance))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    if (mot->tp_ops->set_term_cond(mot->tp, (tp_term_cond_t)c->term_cond, c->tolerance) != TP_OK)
        return mot_refuse(EMCMOT_COMMAND_BAD_EXEC, 1, "planner refused term condition %d",
                          c->term_cond);
    mot->term_cond = c->term_cond;
    mot->tolerance = c->tolerance;
    return EMCMOT_COMMAND_OK;
}

/* SET_MAX_FEED_OVERRIDE: [DISPLAY]MAX_FEED_OVERRIDE. */
int mot_cmd_set_max_feed_override(const emcmot_command_t *c)
{
    if (need_nonnegative(c, c->scale))
        return EMCMOT_COMMAND_INVALID_PARAMS;
    mot->max_feed_override = c->scale;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SETUP_ARC_BLENDS: [TRAJ]ARC_BLEND_*. */
int mot_cmd_setup_arc_blends(const emcmot_command_t *c)
{
    tp_limits_t *l = &mot->tp_limits;

    l->arc_blend_enable = c->arc_blend_enable;
    l->arc_blend_fallback_enable = c->arc_blend_fallback_enable;
    l->arc_blend_optimization_depth = c->arc_blend_optimization_depth;
    l->arc_blend_gap_cycles = c->arc_blend_gap_cycles;
    l->arc_blend_ramp_freq = c->arc_blend_ramp_freq;
    l->arc_blend_tangent_kink_ratio = c->arc_blend_tangent_kink_ratio;
    mot_tp_limits_changed();
    return EMCMOT_COMMAND_OK;
}

/* SET_PROBE_ERR_INHIBIT: [TRAJ]NO_PROBE_JOG_ERROR / NO_PROBE_HOME_ERROR. */
int mot_cmd_set_probe_err_inhibit(const emcmot_command_t *c)
{
    mot->probe_err_inhibit_jog = c->probe_jog_err_inhibit != 0;
    mot->probe_err_inhibit_home = c->probe_home_err_inhibit != 0;
    return EMCMOT_COMMAND_OK;
}

/* SET_DOUT: now (M64/M65) or with the next move (M62/M63). */
int mot_cmd_set_dout(const emcmot_command_t *c)
{
    if (c->io_index < 0 || c->io_index >= mot->num_dio)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "digital output %d does not exist (motmod num_dio=%d)", c->io_index,
                          mot->num_dio);
    if (c->now) {
        mot->dout[c->io_index] = c->dout_start != 0;
        return EMCMOT_COMMAND_OK;
    }
    if (mot->tp_ops->set_dout(mot->tp, c->io_index, c->dout_start != 0, c->dout_end != 0) != TP_OK)
        return mot_refuse(EMCMOT_COMMAND_BAD_EXEC, 1, "planner refused synced digital output %d",
                          c->io_index);
    return EMCMOT_COMMAND_OK;
}

/* SET_AOUT: now (M68) or with the next move (M67). */
int mot_cmd_set_aout(const emcmot_command_t *c)
{
    if (c->io_index < 0 || c->io_index >= mot->num_aio)
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "analog output %d does not exist (motmod num_aio=%d)", c->io_index,
                          mot->num_aio);
    if (c->now) {
        mot->aout[c->io_index] = c->aout_start;
        return EMCMOT_COMMAND_OK;
    }
    if (mot->tp_ops->set_aout(mot->tp, c->io_index, c->aout_start, c->aout_end) != TP_OK)
        return mot_refuse(EMCMOT_COMMAND_BAD_EXEC, 1, "planner refused synced analog output %d",
                          c->io_index);
    return EMCMOT_COMMAND_OK;
}

/* SET_SPINDLESYNC: units per revolution for the moves that follow (0 = unsynced). */
int mot_cmd_set_spindlesync(const emcmot_command_t *c)
{
    if (c->spindle_sync != 0.0 && (c->spindle < 0 || c->spindle >= mot->num_spindles))
        return mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                          "spindle-synchronized motion on non-existent spindle %d", c->spindle);
    mot->spindle_sync = c->spindle_sync;
    mot->spindle_sync_spindle = c->spindle < 0 ? 0 : c->spindle;
    mot->spindle_sync_velocity = c->sync_velocity_mode != 0;
    mot->tp_ops->set_spindle_sync(mot->tp, mot->spindle_sync_spindle, c->spindle_sync,
                                  mot->spindle_sync_velocity);
    return EMCMOT_COMMAND_OK;
}
