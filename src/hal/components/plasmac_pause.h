/* plasmac_pause.h: plasmac while paused: PAUSED_MOTION, consumable change, cut recovery and the
 * laser recovery offset (included by plasmac.comp). */

/* PAUSED_MOTION: move along the path at paused-motion-speed; 0 pauses again. */
static void pm_paused_motion(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (paused_motion_speed != 0) {
        paused_motion = 1;
        adaptive_feed = paused_motion_speed;
        if (program_is_paused) program_resume = 1;
        feed_hold = 0;
        return;
    }
    if (program_is_running) program_pause = 1;
    adaptive_feed = 1;
    paused_motion = 0;
    if (program_is_paused) pm_goto(__comp_inst, PM_CUT_RECOVERY_ON);
}

/* A sensor contact stops a consumable change move (reported once); TRUE while blocked. */
static int pm_cc_blocked(struct __comp_state *__comp_inst)
{
    if (!sensor_active) {
        cc_blocked = 0;
        return 0;
    }
    if (!cc_blocked) {
        pm_msg("breakaway, float, or ohmic activated during consumable change, motion paused.");
        pm_msg("WARNING: MOTION WILL RESUME IMMEDIATELY UPON RESOLVING THIS CONDITION!");
    }
    cc_blocked = 1;
    return 1;
}

/* CONSUMABLE_CHANGE_ON: XY to the change offset while the request is held. */
static void pm_consumable_on(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    consumable_changing = 1;
    if (pm_cc_blocked(__comp_inst)) return;
    if (consumable_change) pm_xy_move(__comp_inst, x_offset, y_offset, pm_speed(__comp_inst, xy_feed_rate));
    else pm_goto(__comp_inst, PM_CONSUMABLE_CHANGE_OFF);
}

/* CONSUMABLE_CHANGE_OFF: XY back; then wait for the resume. */
static void pm_consumable_off(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (pm_cc_blocked(__comp_inst)) return;
    if (!pm_xy_move(__comp_inst, pm_home_x(__comp_inst), pm_home_y(__comp_inst), pm_speed(__comp_inst, xy_feed_rate)))
        return;
    consumable_changing = 0;
    pm_goto(__comp_inst, PM_IDLE);
}

/* The laser recovery offset: set while laser-recovery-start is not 0, removed when it is 0 again. */
static void pm_laser_recovery(struct __comp_state *__comp_inst)
{
    int st = laser_recovery_state;
    if (laser_recovery_start && (st == PM_LASER_OFF || st == PM_LASER_RESETTING)) st = PM_LASER_SET;
    else if (!laser_recovery_start && (st == PM_LASER_ON || st == PM_LASER_SETTING)) st = PM_LASER_RESET;
    if (st == PM_LASER_SET) {
        laser_x = laser_x_offset;
        laser_y = laser_y_offset;
        st = PM_LASER_SETTING;
    } else if (st == PM_LASER_RESET) {
        laser_x = laser_y = 0;
        st = PM_LASER_RESETTING;
    }
    laser_recovery_state = st;
}

/* CUT_RECOVERY_ON: XY to the recovery offset (plus the laser offset) at half cut speed while held. */
static void pm_recovery_on(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    int there;
    if (!cut_recovering && puddle_jump_height > 0 && puddle_jump_height != 100)
        pm_msg("Puddle Jump is disabled during Cut Recovery.");
    cut_recovering = 1;
    recovering = 1;
    if (cut_recovery) {
        x_target = x_offset;
        y_target = y_offset;
    }
    pm_laser_recovery(__comp_inst);
    there = pm_xy_move(__comp_inst, x_target + laser_x, y_target + laser_y, pm_recovery_speed(__comp_inst));
    if (there && laser_recovery_state == PM_LASER_SETTING) laser_recovery_state = PM_LASER_ON;
    if (there && laser_recovery_state == PM_LASER_RESETTING) laser_recovery_state = PM_LASER_OFF;
    if (torch_pulse_start) {
        timer = torch_pulse_time;
        pulse_recovery = 1;
        pm_goto(__comp_inst, PM_TORCHPULSE);
    } else if (!cut_recovery && there && x_target == 0 && y_target == 0 && !laser_x && !laser_y) {
        pm_goto(__comp_inst, PM_CUT_RECOVERY_OFF);
    } else if (!cut_recovery && there && (program_is_running || laser_recovery_state == PM_LASER_OFF)) {
        pm_goto(__comp_inst, PM_IDLE);
    }
}

/* CUT_RECOVERY_OFF: XY back to the path (at cut speed while the program runs), then cut on or idle. */
static void pm_recovery_off(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    int v = program_is_running ? pm_speed(__comp_inst, cut_feed_rate) : pm_recovery_speed(__comp_inst);
    laser_x = laser_y = 0;
    if (!pm_xy_move(__comp_inst, 0, 0, v < 1 ? 1 : v)) return;
    recovering = 0;
    cut_recovering = 0;
    x_target = y_target = 0;
    laser_recovery_state = PM_LASER_OFF;
    if (cut_started && torch_on && program_is_running) {
        feed_hold = 0;
        thc_timer = thc_delay;
        pm_goto(__comp_inst, mode < 2 ? PM_CUT_MODE_01 : PM_CUT_MODE_2);
    } else {
        pm_goto(__comp_inst, PM_IDLE);
    }
}
