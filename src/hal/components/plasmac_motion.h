/* plasmac_motion.h: plasmac states, external offset motion and arc sensing (included by plasmac.comp). */

/* Cut sequence states, the values of state-out. */
enum plasmac_state {
    PM_IDLE, PM_PROBE_HEIGHT, PM_PROBE_DOWN, PM_PROBE_UP, PM_ZERO_HEIGHT, PM_PIERCE_HEIGHT,
    PM_TORCH_ON, PM_ARC_OK, PM_PIERCE_DELAY, PM_PUDDLE_JUMP, PM_CUT_HEIGHT, PM_CUT_MODE_01,
    PM_CUT_MODE_2, PM_END_CUT, PM_SAFE_HEIGHT, PM_MAX_HEIGHT, PM_TORCH_PULSE, PM_PAUSED,
    PM_PROBE_TEST, PM_CONSUMABLE_CHANGE_ON, PM_CONSUMABLE_CHANGE_OFF, PM_PAUSED_MOTION,
    PM_SCRIBE_ARM, PM_SCRIBE_ON, PM_SCRIBING, PM_SPOTTING, PM_OHMIC_RETRY, PM_OFFSET_PROBE,
    PM_OFFSET_RETURN, PM_RECOVER_RETURN, PM_CUT_RECOVERY, PM_LASER_RECOVERY, PM_STATE_COUNT
};

/* Values of stop-type-out. */
enum plasmac_stop { PM_STOP_NONE, PM_STOP_STOP, PM_STOP_PAUSE };

/* Values of error-out. */
enum plasmac_error {
    PM_ERR_NONE, PM_ERR_BREAKAWAY, PM_ERR_FLOAT_SWITCH, PM_ERR_PROBE_LIMIT, PM_ERR_NO_ARC,
    PM_ERR_ARC_LOST, PM_ERR_OUT_OF_LIMITS, PM_ERR_FLOAT_BEFORE_PROBE, PM_ERR_EXTERNAL_ESTOP
};

/* The tool a sequence runs for: the torch (cut), the scribe or a spot. */
enum plasmac_tool { PM_TOOL_TORCH, PM_TOOL_SCRIBE, PM_TOOL_SPOT };

/* Values of laser-recovery-state. */
enum plasmac_laser { PM_LASER_NONE, PM_LASER_MOVING, PM_LASER_THERE, PM_LASER_BACK };

/* Tolerance for height comparisons (machine units). */
#define PM_EPSILON 1e-9

/* Enter a new state and restart its timer. */
static void plasmac_goto(struct __comp_state *__comp_inst, int next)
{
    state = next;
    timer = 0.0;
}

/* Machine units per offset count: one micron in machine units. */
static double plasmac_scale(struct __comp_state *__comp_inst)
{
    double upm = units_per_mm > 0.0 ? units_per_mm : 1.0;
    return 0.001 * upm;
}

/* Current torch Z (programmed Z plus the offset this component applies). */
static double plasmac_z(struct __comp_state *__comp_inst)
{
    return zbase + zoff;
}

/* TRUE when the Z limits describe a usable travel range. */
static int plasmac_z_limits_ok(struct __comp_state *__comp_inst)
{
    return axis_z_max_limit > axis_z_min_limit;
}

/* Clamp an absolute Z target into the Z limits when they are set. */
static double plasmac_clamp_z(struct __comp_state *__comp_inst, double z)
{
    if (!plasmac_z_limits_ok(__comp_inst))
        return z;
    if (z > axis_z_max_limit)
        return axis_z_max_limit;
    if (z < axis_z_min_limit)
        return axis_z_min_limit;
    return z;
}

/* Step a value toward a target by at most step; return 1 once it is there.
   A NaN target or step holds the value (never drift one way on bad input). */
static int plasmac_step_toward(double *value, double target, double step)
{
    double delta = target - *value;
    if (delta != delta || step != step)
        return 0;
    if (step <= 0.0 || fabs(delta) <= step) {
        *value = target;
        return 1;
    }
    *value += delta > 0.0 ? step : -step;
    return 0;
}

/* Move the Z offset toward absolute height z at feed (units/min); 1 when reached. */
static int plasmac_move_z(struct __comp_state *__comp_inst, double z, double feed, double dt)
{
    double target = plasmac_clamp_z(__comp_inst, z) - zbase;
    return plasmac_step_toward(&zoff, target, feed / 60.0 * dt);
}

/* Move the X/Y offsets together toward (tx, ty) at feed (units/min); 1 when reached. */
static int plasmac_move_xy(struct __comp_state *__comp_inst, double tx, double ty, double feed,
                           double dt)
{
    double dx = tx - xoff, dy = ty - yoff, dist = hypot(dx, dy), step = feed / 60.0 * dt;
    if (!isfinite(dx) || !isfinite(dy) || step != step)  /* NaN or infinite target, NaN feed: hold */
        return 0;
    if (step <= 0.0 || dist <= step) {
        xoff = tx;
        yoff = ty;
        return 1;
    }
    xoff += dx / dist * step;
    yoff += dy / dist * step;
    return 0;
}

/* Absolute Z of a height above the recorded material surface. */
static double plasmac_above_zero(struct __comp_state *__comp_inst, double height)
{
    return zzero + height;
}

/* TRUE when no valid arc is required (marking or operator override). */
static int plasmac_ignore_arc(struct __comp_state *__comp_inst)
{
    return ignore_arc_ok_0 || ignore_arc_ok_1 || mesh_enable;
}

/* Arc voltage in volts and arc OK from the source the mode selects. */
static void plasmac_sense(struct __comp_state *__comp_inst)
{
    prev_volts = volts;
    volts = (arc_voltage_in - arc_voltage_offset) * arc_voltage_scale;
    if (mode == 0)
        arc_ok_now = volts >= arc_ok_low && volts <= arc_ok_high;
    else
        arc_ok_now = arc_ok_in;
    arc_ok_now = arc_ok_now && torch_on;
}

/* TRUE for states where motion must wait for the torch (or scribe) to be ready. */
static int plasmac_holds_motion(int s)
{
    return (s >= PM_PROBE_HEIGHT && s <= PM_CUT_HEIGHT) || s == PM_SCRIBE_ARM ||
           s == PM_SCRIBE_ON || s == PM_SPOTTING || s == PM_OHMIC_RETRY ||
           s == PM_OFFSET_PROBE || s == PM_OFFSET_RETURN || s == PM_RECOVER_RETURN;
}

/* Arc voltage as shown: 0 inside zero-window. */
static double plasmac_shown_volts(struct __comp_state *__comp_inst)
{
    return fabs(volts) <= zero_window ? 0.0 : volts;
}

/* TRUE when the ohmic contact circuit must be powered. */
static int plasmac_ohmic_power(struct __comp_state *__comp_inst)
{
    if (state == PM_IDLE && ohmic_test)
        return 1;
    return ohmic_probe_enable && (state == PM_PROBE_DOWN || state == PM_PROBE_HEIGHT ||
                                  state == PM_OHMIC_RETRY);
}

/* Remember the request inputs of this cycle for edge detection next cycle. */
static void plasmac_latch_inputs(struct __comp_state *__comp_inst)
{
    last_start = cutting_start;
    last_probe_test = probe_test;
    last_pulse = torch_pulse_start;
    last_scribe = scribe_start;
    last_spot = spotting_start;
    last_set_probe = offset_set_probe;
}

/* Nearest offset count, saturated at the s32 range (NaN gives 0). */
static int plasmac_counts(double v)
{
    if (v != v)
        return 0;
    if (v >= 2147483647.0)
        return 2147483647;
    if (v <= -2147483648.0)
        return -2147483647 - 1;
    return (int)lround(v);
}

/* Write the offset counts, enables and status outputs for this cycle. */
static void plasmac_outputs(struct __comp_state *__comp_inst)
{
    double scale = plasmac_scale(__comp_inst);
    offset_scale = scale;
    z_offset_counts = plasmac_counts(zoff / scale);
    x_offset_counts = plasmac_counts(xoff / scale);
    y_offset_counts = plasmac_counts(yoff / scale);
    z_offset_enable = machine_is_on;
    xy_offset_enable = machine_is_on;
    feed_hold = plasmac_holds_motion(state);
    x_offset_current = xoff;
    y_offset_current = yoff;
    z_offset_current = zoff;
    arc_voltage_out = plasmac_shown_volts(__comp_inst);
    arc_ok_out = arc_ok_now;
    thc_enabled = thc_enable && !thc_disable && !mesh_enable;
    ohmic_enable = plasmac_ohmic_power(__comp_inst);
    z_height = have_zero ? plasmac_z(__comp_inst) - zzero : 0.0;
    state_out = state;
    if (program_pause && (program_is_paused || program_is_idle))
        program_pause = 0;
    if (program_stop && program_is_idle)
        program_stop = 0;
    if (program_resume && program_is_running && !program_is_paused)
        program_resume = 0;
    plasmac_latch_inputs(__comp_inst);
}
