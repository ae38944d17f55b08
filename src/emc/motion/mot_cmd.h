/* mot_cmd.h: the handlers of the EMCMOT commands (one per code) and their shared helpers. */
#ifndef MOT_CMD_H
#define MOT_CMD_H

#include "mot_priv.h"

typedef int (*mot_cmd_fn_t)(const emcmot_command_t *cmd);

/* Refuse the command being handled: keep the reason for the echo, queue it for the
 * operator when report is set, and return result. */
int mot_refuse(int result, int report, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* The joint of cmd when 0 <= joint < num_joints, else -1 (refused as INVALID_PARAMS). */
int mot_cmd_joint(const emcmot_command_t *cmd);
/* The axis of cmd when 0..8, else -1 (refused). */
int mot_cmd_axis(const emcmot_command_t *cmd);
/* The spindle of cmd when 0 <= spindle < num_spindles, else -1 (refused with text). */
int mot_cmd_spindle(const emcmot_command_t *cmd, const char *text);
/* Non-zero for the commands that add a planner segment. */
int mot_cmd_is_move(int code);
/* Push the planner limits after a configuration change. */
void mot_tp_limits_changed(void);

/* mot_cmd_mode.c */
int mot_cmd_abort(const emcmot_command_t *c);
int mot_cmd_enable(const emcmot_command_t *c);
int mot_cmd_disable(const emcmot_command_t *c);
int mot_cmd_pause(const emcmot_command_t *c);
int mot_cmd_reverse(const emcmot_command_t *c);
int mot_cmd_forward(const emcmot_command_t *c);
int mot_cmd_resume(const emcmot_command_t *c);
int mot_cmd_step(const emcmot_command_t *c);
int mot_cmd_free(const emcmot_command_t *c);
int mot_cmd_coord(const emcmot_command_t *c);
int mot_cmd_teleop(const emcmot_command_t *c);
int mot_cmd_override_limits(const emcmot_command_t *c);
int mot_cmd_set_num_joints(const emcmot_command_t *c);
int mot_cmd_set_num_spindles(const emcmot_command_t *c);
int mot_cmd_set_world_home(const emcmot_command_t *c);
int mot_cmd_set_debug(const emcmot_command_t *c);
int mot_cmd_set_offset(const emcmot_command_t *c);

/* mot_cmd_move.c */
int mot_cmd_set_line(const emcmot_command_t *c);
int mot_cmd_set_circle(const emcmot_command_t *c);
int mot_cmd_probe(const emcmot_command_t *c);
int mot_cmd_rigid_tap(const emcmot_command_t *c);
int mot_cmd_clear_probe_flags(const emcmot_command_t *c);

/* mot_cmd_traj.c */
int mot_cmd_feed_scale(const emcmot_command_t *c);
int mot_cmd_rapid_scale(const emcmot_command_t *c);
int mot_cmd_fs_enable(const emcmot_command_t *c);
int mot_cmd_fh_enable(const emcmot_command_t *c);
int mot_cmd_af_enable(const emcmot_command_t *c);
int mot_cmd_set_vel(const emcmot_command_t *c);
int mot_cmd_set_vel_limit(const emcmot_command_t *c);
int mot_cmd_set_acc(const emcmot_command_t *c);
int mot_cmd_set_jerk(const emcmot_command_t *c);
int mot_cmd_set_planner_type(const emcmot_command_t *c);
int mot_cmd_set_scurve_peak_scale(const emcmot_command_t *c);
int mot_cmd_set_term_cond(const emcmot_command_t *c);
int mot_cmd_set_max_feed_override(const emcmot_command_t *c);
int mot_cmd_setup_arc_blends(const emcmot_command_t *c);
int mot_cmd_set_probe_err_inhibit(const emcmot_command_t *c);
int mot_cmd_set_dout(const emcmot_command_t *c);
int mot_cmd_set_aout(const emcmot_command_t *c);
int mot_cmd_set_spindlesync(const emcmot_command_t *c);

/* mot_cmd_spindle.c */
int mot_cmd_spindle_scale(const emcmot_command_t *c);
int mot_cmd_ss_enable(const emcmot_command_t *c);
int mot_cmd_spindle_on(const emcmot_command_t *c);
int mot_cmd_spindle_off(const emcmot_command_t *c);
int mot_cmd_spindle_increase(const emcmot_command_t *c);
int mot_cmd_spindle_decrease(const emcmot_command_t *c);
int mot_cmd_spindle_brake_engage(const emcmot_command_t *c);
int mot_cmd_spindle_brake_release(const emcmot_command_t *c);
int mot_cmd_spindle_orient(const emcmot_command_t *c);
int mot_cmd_set_spindle_params(const emcmot_command_t *c);

/* mot_cmd_jog.c */
int mot_cmd_jog_cont(const emcmot_command_t *c);
int mot_cmd_jog_incr(const emcmot_command_t *c);
int mot_cmd_jog_abs(const emcmot_command_t *c);
int mot_cmd_jog_abort(const emcmot_command_t *c);

/* mot_cmd_joint.c */
int mot_cmd_joint_activate(const emcmot_command_t *c);
int mot_cmd_joint_deactivate(const emcmot_command_t *c);
int mot_cmd_joint_home(const emcmot_command_t *c);
int mot_cmd_joint_unhome(const emcmot_command_t *c);
int mot_cmd_set_joint_position_limits(const emcmot_command_t *c);
int mot_cmd_set_joint_backlash(const emcmot_command_t *c);
int mot_cmd_set_joint_min_ferror(const emcmot_command_t *c);
int mot_cmd_set_joint_max_ferror(const emcmot_command_t *c);
int mot_cmd_set_joint_vel_limit(const emcmot_command_t *c);
int mot_cmd_set_joint_acc_limit(const emcmot_command_t *c);
int mot_cmd_set_joint_homing_params(const emcmot_command_t *c);
int mot_cmd_set_joint_jerk_limit(const emcmot_command_t *c);
int mot_cmd_update_joint_homing_params(const emcmot_command_t *c);
int mot_cmd_set_joint_motor_offset(const emcmot_command_t *c);
int mot_cmd_set_joint_comp(const emcmot_command_t *c);

/* mot_cmd_axis.c */
int mot_cmd_set_axis_position_limits(const emcmot_command_t *c);
int mot_cmd_set_axis_vel_limit(const emcmot_command_t *c);
int mot_cmd_set_axis_acc_limit(const emcmot_command_t *c);
int mot_cmd_set_axis_locking_joint(const emcmot_command_t *c);
int mot_cmd_set_axis_jerk_limit(const emcmot_command_t *c);

#endif
