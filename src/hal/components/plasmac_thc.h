/* plasmac_thc.h: plasmac's cutting states: feed rate, target voltage, height override, corner and
 * void lock, the arc voltage loop (CUT_MODE_01) and move-up/move-down (CUT_MODE_2). */

/* The feed rate the cut is asked to run at. */
static void pm_requested_feed(struct __comp_state *__comp_inst)
{
    double scale = gcode_scale != 1 && gcode_scale != 0 ? gcode_scale : 1.0, f;
    if (feed_upm != 0) f = adaptive_feed != 0 ? feed_upm / adaptive_feed : feed_upm;
    else f = cut_feed_rate * feed_override;
    requested_feed_rate = f / scale;
}

/* TRUE when the cut runs at (practically) the requested feed rate. */
static int pm_at_speed(struct __comp_state *__comp_inst)
{
    return laser_mode || current_velocity * 60.0 > requested_feed_rate * 0.999;
}

/* The mean of the last n voltages when they all lie within the threshold of the present one, else 0. */
static double pm_auto_target(struct __comp_state *__comp_inst, int n)
{
    double sum = 0;
    if (!pm_ring_near(__comp_inst, n, arc_voltage_out, thc_sample_threshold)) return 0;
    for (int k = 1; k <= n; k++) sum += ring[(ring_idx - k + PM_RING) % PM_RING];
    return sum / n;
}

/* No target yet: corner lock holds until the cut is at speed, then the target is taken. */
static void pm_take_target(struct __comp_state *__comp_inst, double t)
{
    double v = 0;
    cornerlock_is_locked = 1;
    if (!pm_at_speed(__comp_inst)) return;
    if (thc_auto && use_auto_volts) {
        v = pm_auto_target(__comp_inst, pm_clampi(thc_sample_counts, 1, 1000));
    } else if ((thc_timer -= t) <= 0) {
        if (!use_auto_volts) {
            v = cut_volts;
        } else {
            auto_sum += arc_voltage_out;
            if (++auto_n >= target_samples) v = auto_sum / auto_n;
        }
    }
    if (v == 0) return;
    target_volts = v;
    cornerlock_is_locked = 0;
    e_prev = 0;
    v_prev = arc_voltage_out;
}

/* Corner lock below cornerlock-threshold percent of the requested feed, released above 99 percent. */
static void pm_cornerlock(struct __comp_state *__comp_inst)
{
    double vel = current_velocity * 60.0;
    if (!cornerlock_enable) {
        cornerlock_is_locked = 0;
        return;
    }
    if (vel < requested_feed_rate * cornerlock_threshold / 100.0) cornerlock_is_locked = 1;
    else if (vel > requested_feed_rate * 0.99) cornerlock_is_locked = 0;
}

/* Void lock after voidlock-on-cycles steep voltage changes, released after voidlock-off-cycles calm periods. */
static void pm_voidlock(struct __comp_state *__comp_inst, double t)
{
    int steep = fabs(arc_voltage_out - v_prev) > voidlock_slope * voidlock_on_cycles * t;
    v_prev = arc_voltage_out;
    if (!voidlock_enable) {
        voidlock_is_locked = 0;
        void_on_n = void_off_n = 0;
        return;
    }
    void_on_n = steep ? void_on_n + 1 : 0;
    if (void_on_n > voidlock_on_cycles) {
        voidlock_is_locked = 1;
        void_off_n = 0;
    } else if (voidlock_is_locked && !steep && ++void_off_n >= voidlock_off_cycles) {
        voidlock_is_locked = 0;
    }
}

/* Move Z by step counts within the offset range; a step past it stops the cut (0). */
static int pm_thc_step(struct __comp_state *__comp_inst, int step)
{
    int next = z_offset_counts + step;
    led_up = step > 0;
    led_down = step < 0;
    if (step < 0 && next < pm_bottom_counts(__comp_inst)) {
        pm_pause_msg("bottom limit reached while THC moving down.");
        pm_abort(__comp_inst);
        return 0;
    }
    if (step > 0 && next > top_t) {
        pm_pause_msg("top limit reached while THC moving up.");
        pm_abort(__comp_inst);
        return 0;
    }
    z_offset_enable = 1;
    z_offset_counts = next;
    return 1;
}

/* The arc voltage loop: P, I (not accumulated, as LinuxCNC) and D on a tenth of the voltage error. */
static void pm_thc_pid(struct __comp_state *__comp_inst, double t)
{
    int res = pm_clampi(resolution, 1, 1000), v = pm_thc_speed(__comp_inst);
    double e = (target_volts + height_override - arc_voltage_out) * 0.1, step;
    if (fabs(e) < fabs(thc_threshold * 0.1)) e = 0;
    step = e * pid_p_gain * res + e * pid_i_gain * res * t + (t > 0 ? (e - e_prev) * pid_d_gain * res / t : 0);
    e_prev = e;
    if (step > v) step = v;
    if (step < -v) step = -v;
    pm_thc_step(__comp_inst, pm_counts(step));
}

/* Raise the safe height with a torch that rose above the cut datum; report reaching the top once. */
static void pm_safe_follow(struct __comp_state *__comp_inst)
{
    int raise = z_offset_counts - cut_t;
    if (raise <= 0 || safe_base >= top_t) return;
    safe_t = safe_base + raise;
    if (safe_t < top_t) return;
    safe_t = top_t;
    if (safe_height_is_limited) return;
    safe_height_is_limited = 1;
    pm_msg(pm_upm(__comp_inst) == 1.0 ? "safe traverse height has been reduced to less than 13mm."
                                       : "safe traverse height has been reduced to less than 0.5in.");
}

/* A change of height-override moves the torch at setup speed (down for positive volts). */
static int pm_height_override(struct __comp_state *__comp_inst)
{
    if (!ovr_moving && fabs(height_override - override_prev) > PM_HEIGHT_OVERRIDE_STEP) {
        ovr_target = z_offset_counts
                     - pm_to_counts(__comp_inst, (height_override - override_prev) * height_per_volt);
        override_prev = height_override;
        ovr_moving = 1;
    }
    if (ovr_moving && pm_z_move(__comp_inst, ovr_target, pm_setup_speed(__comp_inst))) ovr_moving = 0;
    return ovr_moving;
}

/* Statistics and the end of a manual or idle-program cut. */
static void pm_cut_common(struct __comp_state *__comp_inst, double t)
{
    cut_length += current_velocity * t;
    cut_time += t;
    if (thc_active) thc_was_active = 1;
    if (program_is_idle && !cutting_start) pm_goto(__comp_inst, PM_IDLE);
}

/* CUT_MODE_01: height by arc voltage. */
static void pm_cut_mode_01(struct __comp_state *__comp_inst, double t)
{
    pm_requested_feed(__comp_inst);
    if ((torch_on || laser_mode) && !mesh_enable && !ignore_arc_ok_0 && !ignore_arc_ok_1) {
        if (target_volts == 0) {
            pm_take_target(__comp_inst, t);
        } else if (!pm_height_override(__comp_inst) && thc_enabled) {
            pm_cornerlock(__comp_inst);
            pm_voidlock(__comp_inst, t);
            if (!cornerlock_is_locked && !voidlock_is_locked) pm_thc_pid(__comp_inst, t);
        }
        pm_safe_follow(__comp_inst);
    }
    if (state_out == PM_CUT_MODE_01) pm_cut_common(__comp_inst, t);
}

/* CUT_MODE_2: height by move-up/move-down at the THC speed. */
static void pm_cut_mode_2(struct __comp_state *__comp_inst, double t)
{
    int v = pm_thc_speed(__comp_inst);
    pm_requested_feed(__comp_inst);
    led_up = led_down = 0;
    if (thc_enabled && arc_ok_out) {
        pm_cornerlock(__comp_inst);
        if (!cornerlock_is_locked && move_up != move_down) pm_thc_step(__comp_inst, move_up ? v : -v);
        pm_safe_follow(__comp_inst);
    }
    if (state_out == PM_CUT_MODE_2) pm_cut_common(__comp_inst, t);
}
