/* plasmac_probe.h: plasmac's IDLE decisions and material probing (PROBE_HEIGHT, PROBE_DOWN,
 * PROBE_UP, ZERO_HEIGHT) (included by plasmac.comp). */

/* A pause for a failed probe, or for a probe test the error flag. */
static void pm_probe_failed(struct __comp_state *__comp_inst, const char *why)
{
    if (probe_test) {
        pm_msg(why);
        pm_msg("probe test aborted.");
        probe_test_error = 1;
        torch_on = 0;
        pm_goto(__comp_inst, PM_MAX_HEIGHT);
    } else {
        pm_pause_msg(why);
        pm_abort(__comp_inst);
    }
}

/* TRUE when the next cut starts close enough to the last one to skip probing. */
static int pm_skip_ihs(struct __comp_state *__comp_inst)
{
    double ref_x = thc_was_active ? end_x : start_x, ref_y = thc_was_active ? end_y : start_y;
    if (skip_ihs_distance == 0 || probe_required || !has_zero) return 0;
    return hypot(axis_x_position - ref_x, axis_y_position - ref_y) < skip_ihs_distance;
}

/* An offset probe position outside the X/Y limits: its message, or NULL. */
static const char *pm_probe_offset_fault(struct __comp_state *__comp_inst)
{
    double x = axis_x_position + offset_probe_x, y = axis_y_position + offset_probe_y;
    if (offset_probe_x == 0 && offset_probe_y == 0) return NULL;
    if (x < axis_x_min_limit) return "probe offset would violate axis X minimum limit.";
    if (x > axis_x_max_limit) return "probe offset would violate axis X maximum limit.";
    if (y < axis_y_min_limit) return "probe offset would violate axis Y minimum limit.";
    if (y > axis_y_max_limit) return "probe offset would violate axis Y maximum limit.";
    return NULL;
}

/* The counts where probing down starts (never above the torch). */
static int pm_probe_start(struct __comp_state *__comp_inst)
{
    double z = axis_z_position;
    int c;
    if (first_cut && material_thickness + slat_height > 0)
        z = axis_z_min_limit + material_thickness + slat_height;
    else if (probe_start_height > 0)
        z = axis_z_min_limit + probe_start_height;
    c = pm_z_counts_at(__comp_inst, z);
    return c < z_offset_counts ? c : z_offset_counts;
}

/* A cut, spot or probe test starts: skip probing, refuse, or probe. */
static void pm_torch_start(struct __comp_state *__comp_inst)
{
    const char *why;
    char line[80];
    feed_hold = 1;
    cut_started = 1;
    if (pm_skip_ihs(__comp_inst)) {
        start_x = axis_x_position;
        start_y = axis_y_position;
        pm_goto(__comp_inst, PM_PIERCE_HEIGHT);
        return;
    }
    if (sensor_active) {
        rtapi_snprintf(line, sizeof(line), "%s detected before probing.",
                       breakaway ? "breakaway switch" : float_switch ? "float switch" : "ohmic probe");
        pm_probe_failed(__comp_inst, line);
        return;
    }
    if ((why = pm_probe_offset_fault(__comp_inst)) != NULL) {
        pm_probe_failed(__comp_inst, why);
        return;
    }
    laser_x = laser_y = 0;
    laser_recovery_state = PM_LASER_OFF;
    start_x = axis_x_position;
    start_y = axis_y_position;
    probe_start = pm_probe_start(__comp_inst);
    offset_probing = offset_probe_x != 0 || offset_probe_y != 0;
    probe_retry = 0;
    ohmic_tries = 0;
    pm_goto(__comp_inst, PM_PROBE_HEIGHT);
}

/* TRUE when a cut may start now (homed, not stopped, a cutting or spotting tool or a probe test). */
static int pm_start_wanted(struct __comp_state *__comp_inst)
{
    int tool_ok = tool == PM_TOOL_CUTTING || tool == PM_TOOL_SPOTTING || probe_test;
    return tool_ok && homed && (stop_type_out == PM_STOP_NONE || stop_type_out == PM_STOP_WAIT);
}

/* A tube cut starts without probing: at the current height. */
static void pm_tube_start(struct __comp_state *__comp_inst)
{
    cut_started = 1;
    zero = z_offset_counts;
    cut_t = pierce_t = z_offset_counts;
    top_t = safe_t = safe_base = pm_top_counts(__comp_inst);
    if (torch_enable) {
        restart_timer = 0;
        pm_goto(__comp_inst, PM_TORCH_ON);
    } else {
        thc_timer = thc_delay;
        pm_goto(__comp_inst, PM_CUT_MODE_01);
    }
}

/* The requests handled in IDLE while the program is paused or stopped by plasmac. */
static int pm_idle_paused(struct __comp_state *__comp_inst)
{
    int paused = stop_type_out == PM_STOP_PAUSE || stop_type_out == PM_STOP_WAIT;
    if (paused_motion_speed != 0 && paused && program_is_paused) pm_goto(__comp_inst, PM_PAUSED_MOTION);
    else if (consumable_change && program_is_paused && !consumable_changing) pm_goto(__comp_inst, PM_MAX_HEIGHT);
    else if (consumable_changing && !consumable_change) pm_goto(__comp_inst, PM_CONSUMABLE_CHANGE_OFF);
    else if (cut_recovery && stop_type_out == PM_STOP_PAUSE) pm_goto(__comp_inst, PM_CUT_RECOVERY_ON);
    else return 0;
    return 1;
}

/* IDLE: the first request that applies. */
static void pm_idle(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (mode == 2 && program_is_idle) {
        led_up = move_up;
        led_down = move_down;
    }
    if (probe_inhibit) {
        if (sensor_active) return;
        probe_inhibit = 0;
    }
    if (pm_idle_paused(__comp_inst)) return;
    if (job && program_is_idle) pm_goto(__comp_inst, PM_END_JOB);
    else if (tube_cut && tool == PM_TOOL_CUTTING && pm_start_wanted(__comp_inst)) pm_tube_start(__comp_inst);
    else if (pm_start_wanted(__comp_inst)) pm_torch_start(__comp_inst);
    else if (program_is_running && stop_type_out == PM_STOP_PAUSE) {
        stop_type_out = PM_STOP_NONE;
        if (motion_type == 1) feed_hold = 0;
    } else if (torch_pulse_start) {
        timer = torch_pulse_time;
        pulse_recovery = 0;
        pm_goto(__comp_inst, PM_TORCHPULSE);
    } else if (ohmic_test) {
        ohmic_enable = 1;
        pm_goto(__comp_inst, PM_OHMIC_TEST);
    } else if (tool == PM_TOOL_SCRIBE) {
        scribe_phase = 0;
        timer = scribe_arm_delay;
        pm_goto(__comp_inst, PM_SCRIBING);
    } else if (!cut_started) {
        feed_hold = 0;
    }
}

/* TRUE while the probe touches: the float switch or (with ohmic probing) the ohmic contact. */
static int pm_contact(struct __comp_state *__comp_inst)
{
    return float_switch || (ohmic_probe_enable && ohmic_probe);
}

/* PROBE_HEIGHT: to the probe start (and the offset probe position) at setup speed. */
static void pm_probe_height(struct __comp_state *__comp_inst, double t)
{
    int xy_there = 1;
    probe_time += t;
    if (ohmic_probe_enable) ohmic_enable = 1;
    if (offset_probing)
        xy_there = pm_xy_move(__comp_inst, pm_home_x(__comp_inst) + pm_to_counts(__comp_inst, offset_probe_x),
                              pm_home_y(__comp_inst) + pm_to_counts(__comp_inst, offset_probe_y),
                              pm_speed(__comp_inst, offset_feed_rate));
    if (pm_contact(__comp_inst)) {
        if (z_offset_counts + pm_to_counts(__comp_inst, pierce_height + pm_mm(__comp_inst, PM_MM_CLEAR))
            > pm_top_counts(__comp_inst)) {
            pm_probe_failed(__comp_inst, "material is too high for safe traverse.");
            return;
        }
        probe_retry = 1;
        pm_goto(__comp_inst, PM_PROBE_UP);
        return;
    }
    if (pm_z_move(__comp_inst, probe_start, pm_setup_speed(__comp_inst)) && xy_there) {
        timer = offset_probing ? offset_probe_delay : 0;
        pm_goto(__comp_inst, PM_PROBE_DOWN);
    }
}

/* PROBE_DOWN: down at probe speed until a contact or the bottom guard. */
static void pm_probe_down(struct __comp_state *__comp_inst, double t)
{
    int bottom = pm_bottom_counts(__comp_inst);
    probe_time += t;
    if (timer > 0) {
        timer -= t;
        return;
    }
    if (float_switch && ohmic_probe_enable && ohmic_tries < ohmic_max_attempts && !ohmic_probe) {
        ohmic_tries++;
        probe_retry = 1;
        pm_goto(__comp_inst, PM_PROBE_UP);
    } else if (float_switch || (ohmic_probe_enable && ohmic_probe)) {
        probe_type = (ohmic_probe_enable && ohmic_probe) ? PM_PROBE_OHMIC : PM_PROBE_FLOAT;
        pm_goto(__comp_inst, PM_PROBE_UP);
    } else if (z_offset_counts - pm_probe_speed(__comp_inst) <= bottom) {
        pm_probe_failed(__comp_inst, "bottom limit reached while probing down.");
    } else {
        pm_z_move(__comp_inst, bottom, pm_probe_speed(__comp_inst));
    }
}

/* Zero and every cut height from the probed surface; 0 when the material is too high. */
static int pm_set_zero(struct __comp_state *__comp_inst)
{
    double travel = probe_type == PM_PROBE_OHMIC ? ohmic_probe_offset : float_switch_travel, pj = puddle_jump_height;
    char line[80];
    zero = z_offset_counts + pm_to_counts(__comp_inst, travel);
    has_zero = 1;
    probe_required = first_cut = 0;
    top_t = pm_top_counts(__comp_inst);
    pierce_t = pm_height(__comp_inst, pierce_height);
    cut_t = pm_height(__comp_inst, cut_height);
    pierce_end_t = pm_height(__comp_inst, pierce_end_height);
    puddle_t = pj > 0 && pj != 100 ? pm_height(__comp_inst, pierce_height * pj / 100.0) : pierce_t;
    if (pierce_t + pm_to_counts(__comp_inst, pm_mm(__comp_inst, PM_MM_CLEAR)) > top_t) return 0;
    safe_t = safe_height == 0 ? top_t : pm_height(__comp_inst, safe_height);
    if (safe_t > top_t) {
        safe_t = top_t;
        safe_height_is_limited = 1;
        double h = (top_t - zero) * offset_scale;
        if (pm_upm(__comp_inst) == 1.0) rtapi_snprintf(line, sizeof(line), "safe traverse height has been reduced to %0.1fmm.", h);
        else rtapi_snprintf(line, sizeof(line), "safe traverse height has been reduced to %0.2fin.", h);
        pm_msg(line);
    }
    safe_base = safe_t;
    return 1;
}

/* PROBE_UP: up while touching (fast on a retry, else probe-final-speed), then zero or probe again. */
static void pm_probe_up(struct __comp_state *__comp_inst, double t)
{
    int res = pm_clampi(resolution, 1, 1000);
    int v = probe_retry ? 10 * res : pm_clampi(probe_final_speed, 1, 10) * res;
    int touching = probe_retry ? pm_contact(__comp_inst)
                               : (probe_type == PM_PROBE_OHMIC ? ohmic_probe : float_switch);
    probe_time += t;
    if (touching) {
        int top = pm_top_counts(__comp_inst);
        pm_z_move(__comp_inst, top > z_offset_counts ? top : z_offset_counts, v);
        return;
    }
    if (probe_retry) {
        probe_retry = 0;
        pm_goto(__comp_inst, PM_PROBE_DOWN);
    } else if (!pm_set_zero(__comp_inst)) {
        pm_probe_failed(__comp_inst, "material is too high for safe traverse.");
    } else {
        pm_goto(__comp_inst, PM_ZERO_HEIGHT);
    }
}

/* ZERO_HEIGHT: the offset probe position returns; then to pierce height. */
static void pm_zero_height(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (offset_probing && !pm_xy_move(__comp_inst, pm_home_x(__comp_inst), pm_home_y(__comp_inst),
                                      pm_speed(__comp_inst, offset_feed_rate)))
        return;
    offset_probing = 0;
    pm_goto(__comp_inst, PM_PIERCE_HEIGHT);
}
