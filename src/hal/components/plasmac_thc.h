/* plasmac_thc.h: plasmac torch height control while cutting (included by plasmac.comp). */

/* Kerf crossing rate threshold at kerfcross-override 100%, in volts per second. */
#define PM_KERF_RATE_BASE 1000.0

/* Clear the height control state and its outputs before a cut or after it. */
static void plasmac_thc_reset(struct __comp_state *__comp_inst)
{
    pid_int = 0.0;
    pid_prev = 0.0;
    volts_sum = 0.0;
    volts_n = 0;
    volts_target = 0.0;
    thc_active = 0;
    led_up = 0;
    led_down = 0;
    cornerlock_is_locked = 0;
    kerfcross_is_locked = 0;
    voidlock_is_locked = 0;
    void_on = 0;
    void_off = 0;
}

/* TRUE while the tool runs slower than the corner lock threshold. */
static int plasmac_cornerlock(struct __comp_state *__comp_inst)
{
    double ref = cut_feed_rate > 0.0 ? cut_feed_rate * feed_override / 60.0 : requested_velocity;
    return cornerlock_enable && current_velocity < ref * cornerlock_threshold / 100.0;
}

/* Kerf crossing lock: set on a fast voltage rise, cleared back near the target. */
static int plasmac_kerfcross(struct __comp_state *__comp_inst, double target, double dt)
{
    double rate = dt > 0.0 ? (volts - prev_volts) / dt : 0.0;
    if (!kerfcross_enable)
        return 0;
    if (rate > PM_KERF_RATE_BASE * kerfcross_override / 100.0)
        return 1;
    if (kerfcross_is_locked && fabs(target - volts) <= thc_threshold)
        return 0;
    return kerfcross_is_locked;
}

/* Void lock: set after voidlock-on-cycles steep rises, released after voidlock-off-cycles near the target. */
static int plasmac_voidlock(struct __comp_state *__comp_inst, double target, double dt)
{
    double rate = dt > 0.0 ? (volts - prev_volts) / dt : 0.0;
    if (!voidlock_enable)
        return 0;
    void_on = rate > voidlock_slope ? void_on + 1 : 0;
    if (void_on >= (voidlock_on_cycles > 0 ? voidlock_on_cycles : 1)) {
        void_off = 0;
        return 1;
    }
    if (!voidlock_is_locked)
        return 0;
    void_off = fabs(target - volts) <= thc_threshold ? void_off + 1 : 0;
    return void_off < voidlock_off_cycles;
}

/* TRUE when this cycle's voltage is steady enough to be an auto volts sample. */
static int plasmac_sample_steady(struct __comp_state *__comp_inst)
{
    return thc_sample_threshold <= 0.0 || fabs(volts - prev_volts) <= thc_sample_threshold;
}

/* Target arc voltage; returns 0 while auto volts is still sampling. */
static int plasmac_target_volts(struct __comp_state *__comp_inst, double *target)
{
    int samples = thc_sample_counts > 0 ? thc_sample_counts : 1;
    if (!use_auto_volts) {
        *target = cut_volts + height_override;
        return 1;
    }
    if (volts_n < samples) {
        if (!plasmac_sample_steady(__comp_inst)) {
            volts_sum = 0.0;
            volts_n = 0;
            return 0;
        }
        volts_sum += volts;
        if (++volts_n < samples)
            return 0;
        volts_target = volts_sum / samples;
    }
    *target = volts_target + height_override;
    return 1;
}

/* Torch velocity (units/s) from the voltage PID, 0 inside the threshold. */
static double plasmac_pid_velocity(struct __comp_state *__comp_inst, double target, double dt)
{
    double err = target - volts, out;
    if (fabs(err) <= thc_threshold) {
        pid_prev = err;
        return 0.0;
    }
    pid_int += err * dt;
    out = pid_p_gain * err + pid_i_gain * pid_int;
    if (dt > 0.0)
        out += pid_d_gain * (err - pid_prev) / dt;
    pid_prev = err;
    if (out > 100.0)
        out = 100.0;
    if (out < -100.0)
        out = -100.0;
    return thc_feed_rate / 60.0 * out / 100.0;
}

/* Velocity from the voltage loop (mode 0/1), or 0 while a lock or auto volts holds it. */
static double plasmac_voltage_velocity(struct __comp_state *__comp_inst, double dt, int *active)
{
    double target = 0.0;
    int known = plasmac_target_volts(__comp_inst, &target);
    kerfcross_is_locked = known && plasmac_kerfcross(__comp_inst, target, dt);
    voidlock_is_locked = known && plasmac_voidlock(__comp_inst, target, dt);
    *active = *active && known && !kerfcross_is_locked && !voidlock_is_locked;
    return *active ? plasmac_pid_velocity(__comp_inst, target, dt) : 0.0;
}

/* Apply a correction velocity within max-offset of cut height and the Z limits. */
static void plasmac_correct(struct __comp_state *__comp_inst, double vel, double dt)
{
    double cut_z = plasmac_above_zero(__comp_inst, cut_height);
    double z = plasmac_z(__comp_inst) + vel * dt;
    if (max_offset > 0.0 && z > cut_z + max_offset)
        z = cut_z + max_offset;
    if (max_offset > 0.0 && z < cut_z - max_offset)
        z = cut_z - max_offset;
    z = plasmac_clamp_z(__comp_inst, z);
    led_up = z > plasmac_z(__comp_inst) + PM_EPSILON;
    led_down = z < plasmac_z(__comp_inst) - PM_EPSILON;
    zoff = z - zbase;
}

/* Add the distance and time of this cycle to the cut statistics. */
static void plasmac_cut_stats(struct __comp_state *__comp_inst, double dt)
{
    if (arc_ok_now || plasmac_ignore_arc(__comp_inst)) {
        cut_time += dt;
        cut_length += hypot(axis_x_position - prev_x, axis_y_position - prev_y);
    }
    prev_x = axis_x_position;
    prev_y = axis_y_position;
}

/* One cutting cycle: feed reduction, locks and the torch height correction. */
static void plasmac_cut(struct __comp_state *__comp_inst, double dt, int up_down)
{
    int active, feed_move = motion_type == 2 || motion_type == 3;
    double vel = 0.0;
    timer += dt;
    plasmac_cut_stats(__comp_inst, dt);
    adaptive_feed = feed_reduction > 0.0 && feed_reduction < 100.0 ? feed_reduction / 100.0 : 1.0;
    led_up = led_down = 0;
    if (!(thc_enable && !thc_disable && !mesh_enable)) {
        thc_active = 0;
        cornerlock_is_locked = 0;
        kerfcross_is_locked = 0;
        voidlock_is_locked = 0;
        plasmac_move_z(__comp_inst, plasmac_above_zero(__comp_inst, cut_height) +
                       height_override * height_per_volt, thc_feed_rate, dt);
        return;
    }
    cornerlock_is_locked = plasmac_cornerlock(__comp_inst);
    active = timer >= thc_delay && feed_move && !cornerlock_is_locked;
    if (up_down)
        vel = active ? (move_up - move_down) * thc_feed_rate / 60.0 : 0.0;
    else if (timer >= thc_delay)
        vel = plasmac_voltage_velocity(__comp_inst, dt, &active);
    thc_active = active;
    if (vel != 0.0)
        plasmac_correct(__comp_inst, vel, dt);
}
