/* plasmac_states.h: plasmac cut sequence as a table of state handlers (included by plasmac.comp). */

/* A state handler runs once per cycle while its state is current. */
typedef void (*plasmac_handler_t)(struct __comp_state *__comp_inst, double dt);

/* Torch off, full feed and height control cleared when a cut ends in any way. */
static void plasmac_leave_cut(struct __comp_state *__comp_inst)
{
    torch_on = 0;
    scribe_arm = 0;
    scribe_on = 0;
    adaptive_feed = 1.0;
    plasmac_thc_reset(__comp_inst);
}

/* The start request of the running tool: cutting-start, scribe-start or spotting-start. */
static int plasmac_request(struct __comp_state *__comp_inst)
{
    if (tool == PM_TOOL_SCRIBE)
        return scribe_start || offset_set_scribe;
    if (tool == PM_TOOL_SPOT)
        return spotting_start;
    return cutting_start;
}

/* TRUE while a probe test (probe-test or offset-set-probe) is requested. */
static int plasmac_probe_test_request(struct __comp_state *__comp_inst)
{
    return probe_test || offset_set_probe;
}

/* TRUE when the torch may be lit for a cut, spot or pulse. */
static int plasmac_torch_allowed(struct __comp_state *__comp_inst)
{
    return torch_enable && !torch_off && !external_estop;
}

/* Switch the torch off and leave the cut through MAX_HEIGHT with a pause or stop request. */
static void plasmac_abort(struct __comp_state *__comp_inst, int error, int stop)
{
    plasmac_leave_cut(__comp_inst);
    if (error)
        error_out = error;
    stop_type_out = stop;
    if (stop == PM_STOP_PAUSE) {
        program_pause = 1;
        seen_paused = 0;
    } else if (stop == PM_STOP_STOP) {
        program_stop = 1;
    }
    plasmac_goto(__comp_inst, PM_MAX_HEIGHT);
}

/* A probe found no material: a probe test reports it, a cut stops the program. */
static void plasmac_probe_failed(struct __comp_state *__comp_inst)
{
    if (probe_testing) {
        probe_test_error = 1;
        probe_testing = 0;
        plasmac_goto(__comp_inst, PM_MAX_HEIGHT);
        return;
    }
    plasmac_abort(__comp_inst, PM_ERR_PROBE_LIMIT, PM_STOP_STOP);
}

/* Begin probing, unless the float switch is already closed; move to the probe offset first. */
static void plasmac_begin_probe(struct __comp_state *__comp_inst, int use_offset)
{
    have_zero = 0;
    ohmic_tries = 0;
    probe_x0 = xoff;
    probe_y0 = yoff;
    probe_offset_used = use_offset && (offset_probe_x != 0.0 || offset_probe_y != 0.0);
    if (float_switch) {
        if (probe_testing)
            plasmac_probe_failed(__comp_inst);
        else
            plasmac_abort(__comp_inst, PM_ERR_FLOAT_BEFORE_PROBE, PM_STOP_PAUSE);
        return;
    }
    plasmac_goto(__comp_inst, probe_offset_used ? PM_OFFSET_PROBE : PM_PROBE_HEIGHT);
}

/* Start (or restart after a pause) a cut: probe unless close enough to the last cut. */
static void plasmac_start_cut(struct __comp_state *__comp_inst)
{
    double dist = hypot(axis_x_position - end_x, axis_y_position - end_y);
    error_out = PM_ERR_NONE;
    stop_type_out = PM_STOP_NONE;
    starts = 0;
    lost_timer = 0.0;
    plasmac_thc_reset(__comp_inst);
    if (zoff == 0.0)
        zbase = axis_z_position;
    if (have_zero && skip_ihs_distance > 0.0 && dist < skip_ihs_distance)
        plasmac_goto(__comp_inst, PM_PIERCE_HEIGHT);
    else
        plasmac_begin_probe(__comp_inst, 1);
}

/* Start a probe test (held at pierce height); offset-set-probe skips the probe offset. */
static void plasmac_start_probe_test(struct __comp_state *__comp_inst, int use_offset)
{
    probe_testing = 1;
    probe_test_error = 0;
    tool = PM_TOOL_TORCH;
    if (zoff == 0.0)
        zbase = axis_z_position;
    plasmac_begin_probe(__comp_inst, use_offset);
}

/* Start the sequence of a tool on its rising start edge; 1 when one started. */
static int plasmac_idle_tool_start(struct __comp_state *__comp_inst)
{
    if (cutting_start && !last_start) {
        tool = PM_TOOL_TORCH;
        if (out_of_limits)
            plasmac_abort(__comp_inst, PM_ERR_OUT_OF_LIMITS, PM_STOP_STOP);
        else if (plasmac_torch_allowed(__comp_inst))
            plasmac_start_cut(__comp_inst);
        return 1;
    }
    if (multi_tool && spotting_start && !last_spot && plasmac_torch_allowed(__comp_inst)) {
        tool = PM_TOOL_SPOT;
        plasmac_start_cut(__comp_inst);
        return 1;
    }
    if ((multi_tool && scribe_start && !last_scribe) || (offset_set_scribe && program_is_idle)) {
        tool = PM_TOOL_SCRIBE;
        scribe_arm = 1;
        plasmac_goto(__comp_inst, PM_SCRIBE_ARM);
        return 1;
    }
    return 0;
}

/* IDLE: start a tool, a probe test or a torch pulse; remove the offsets when the program ends. */
static void plasmac_idle(struct __comp_state *__comp_inst, double dt)
{
    (void)dt;
    torch_on = 0;
    adaptive_feed = 1.0;
    if (plasmac_idle_tool_start(__comp_inst))
        return;
    if (probe_test && !last_probe_test && program_is_idle) {
        plasmac_start_probe_test(__comp_inst, 1);
    } else if (offset_set_probe && !last_set_probe && program_is_idle) {
        plasmac_start_probe_test(__comp_inst, 0);
    } else if (torch_pulse_start && !last_pulse && plasmac_torch_allowed(__comp_inst) &&
               program_is_idle) {
        torch_on = 1;
        plasmac_goto(__comp_inst, PM_TORCH_PULSE);
    } else if ((zoff != 0.0 || xoff != 0.0 || yoff != 0.0) && program_is_idle && !cutting_start) {
        plasmac_goto(__comp_inst, PM_MAX_HEIGHT);
    }
}

/* TRUE when the float switch or (if enabled) the ohmic sense touches the material. */
static int plasmac_contact(struct __comp_state *__comp_inst)
{
    return float_switch || (ohmic_probe_enable && ohmic_probe);
}

/* Record the contact height and go on to find the surface. */
static void plasmac_touched(struct __comp_state *__comp_inst)
{
    zcontact = plasmac_z(__comp_inst);
    contact_float = float_switch;
    if (contact_float && ohmic_probe_enable && !ohmic_probe && ohmic_tries < ohmic_max_attempts) {
        ohmic_tries++;
        plasmac_goto(__comp_inst, PM_OHMIC_RETRY);
        return;
    }
    plasmac_goto(__comp_inst, contact_float ? PM_PROBE_UP : PM_ZERO_HEIGHT);
}

/* PROBE_HEIGHT: fast move down to the probe start height. */
static void plasmac_probe_height(struct __comp_state *__comp_inst, double dt)
{
    double start_z = axis_z_min_limit + probe_start_height;
    if (!plasmac_z_limits_ok(__comp_inst)) {
        plasmac_probe_failed(__comp_inst);
    } else if (plasmac_contact(__comp_inst)) {
        plasmac_touched(__comp_inst);
    } else if (plasmac_z(__comp_inst) <= start_z ||
               plasmac_move_z(__comp_inst, start_z, setup_feed_rate, dt)) {
        plasmac_goto(__comp_inst, PM_PROBE_DOWN);
    }
}

/* PROBE_DOWN: slow move down until contact, failing at the Z minimum limit. */
static void plasmac_probe_down(struct __comp_state *__comp_inst, double dt)
{
    if (plasmac_contact(__comp_inst))
        plasmac_touched(__comp_inst);
    else if (plasmac_z(__comp_inst) <= axis_z_min_limit + PM_EPSILON)
        plasmac_probe_failed(__comp_inst);
    else
        plasmac_move_z(__comp_inst, axis_z_min_limit, probe_feed_rate, dt);
}

/* PROBE_UP: slow move up until the float switch opens again. */
static void plasmac_probe_up(struct __comp_state *__comp_inst, double dt)
{
    if (!float_switch) {
        zcontact = plasmac_z(__comp_inst);
        plasmac_goto(__comp_inst, PM_ZERO_HEIGHT);
    } else if (plasmac_move_z(__comp_inst, axis_z_max_limit, probe_feed_rate, dt)) {
        plasmac_probe_failed(__comp_inst);
    }
}

/* ZERO_HEIGHT: record the material surface. */
static void plasmac_zero_height(struct __comp_state *__comp_inst, double dt)
{
    (void)dt;
    zzero = zcontact + (contact_float ? float_switch_travel : ohmic_probe_offset);
    have_zero = 1;
    if (probe_offset_used)
        plasmac_goto(__comp_inst, PM_OFFSET_RETURN);
    else
        plasmac_goto(__comp_inst, probe_testing ? PM_PROBE_TEST : PM_PIERCE_HEIGHT);
}

/* PIERCE_HEIGHT: move to pierce height. */
static void plasmac_pierce_height(struct __comp_state *__comp_inst, double dt)
{
    if (plasmac_move_z(__comp_inst, plasmac_above_zero(__comp_inst, pierce_height),
                       setup_feed_rate, dt))
        plasmac_goto(__comp_inst, tool == PM_TOOL_SPOT ? PM_SPOTTING : PM_TORCH_ON);
}

/* TORCH_ON: switch the torch on, after the restart delay when this is a restart. */
static void plasmac_torch_on(struct __comp_state *__comp_inst, double dt)
{
    timer += dt;
    if (starts > 0 && timer < arc_restart_delay)
        return;
    torch_on = 1;
    plasmac_goto(__comp_inst, PM_ARC_OK);
}

/* ARC_OK: wait for a valid arc; restart the torch or pause after too many starts. */
static void plasmac_arc_ok(struct __comp_state *__comp_inst, double dt)
{
    int max_starts = arc_max_starts > 0 ? arc_max_starts : 1;
    timer += dt;
    if (arc_ok_now || plasmac_ignore_arc(__comp_inst)) {
        pierce_count++;
        plasmac_goto(__comp_inst, PM_PIERCE_DELAY);
    } else if (!(timer < arc_fail_delay)) {  /* a NaN delay has expired: no endless start */
        torch_on = 0;
        if (++starts >= max_starts)
            plasmac_abort(__comp_inst, PM_ERR_NO_ARC, PM_STOP_PAUSE);
        else
            plasmac_goto(__comp_inst, PM_TORCH_ON);
    }
}

/* PIERCE_DELAY: wait at pierce height, then puddle jump or go to cut height. */
static void plasmac_pierce_delay(struct __comp_state *__comp_inst, double dt)
{
    timer += dt;
    if (timer >= pierce_delay && cut_type == 1) {
        plasmac_leave_cut(__comp_inst);
        plasmac_goto(__comp_inst, PM_END_CUT);
    } else if (timer >= pierce_delay)
        plasmac_goto(__comp_inst, puddle_jump_height > 0.0 ? PM_PUDDLE_JUMP : PM_CUT_HEIGHT);
}

/* PUDDLE_JUMP: wait at a percentage of pierce height. */
static void plasmac_puddle_jump(struct __comp_state *__comp_inst, double dt)
{
    double z = plasmac_above_zero(__comp_inst, pierce_height * puddle_jump_height / 100.0);
    if (!plasmac_move_z(__comp_inst, z, setup_feed_rate, dt))
        return;
    timer += dt;
    if (timer >= puddle_jump_delay)
        plasmac_goto(__comp_inst, PM_CUT_HEIGHT);
}

/* CUT_HEIGHT: move to cut height, then release motion into the cut mode. */
static void plasmac_cut_height(struct __comp_state *__comp_inst, double dt)
{
    if (!plasmac_move_z(__comp_inst, plasmac_above_zero(__comp_inst, cut_height),
                        setup_feed_rate, dt))
        return;
    plasmac_thc_reset(__comp_inst);
    prev_x = axis_x_position;
    prev_y = axis_y_position;
    if (xoff != 0.0 || yoff != 0.0)
        plasmac_goto(__comp_inst, PM_RECOVER_RETURN);
    else
        plasmac_goto(__comp_inst, mode == 2 ? PM_CUT_MODE_2 : PM_CUT_MODE_01);
}

/* CUT_MODE_01: cut with arc voltage height control. */
static void plasmac_cut_mode_01(struct __comp_state *__comp_inst, double dt)
{
    plasmac_cut(__comp_inst, dt, 0);
}

/* CUT_MODE_2: cut with move-up/move-down height control. */
static void plasmac_cut_mode_2(struct __comp_state *__comp_inst, double dt)
{
    plasmac_cut(__comp_inst, dt, 1);
}

/* END_CUT: torch off, remember where the cut ended, then raise the torch. */
static void plasmac_end_cut(struct __comp_state *__comp_inst, double dt)
{
    (void)dt;
    end_x = axis_x_position;
    end_y = axis_y_position;
    plasmac_goto(__comp_inst, have_zero && safe_height > 0.0 ? PM_SAFE_HEIGHT : PM_MAX_HEIGHT);
}

/* SAFE_HEIGHT: move to safe height above the material, then wait for the next cut. */
static void plasmac_safe_height(struct __comp_state *__comp_inst, double dt)
{
    if (plasmac_move_z(__comp_inst, plasmac_above_zero(__comp_inst, safe_height),
                       setup_feed_rate, dt))
        plasmac_goto(__comp_inst, PM_IDLE);
}

/* MAX_HEIGHT: move the offsets back to 0, then idle or wait in the pause. */
static void plasmac_max_height(struct __comp_state *__comp_inst, double dt)
{
    int z_done = plasmac_move_z(__comp_inst, zbase, setup_feed_rate, dt);
    int xy_done = plasmac_move_xy(__comp_inst, 0.0, 0.0, xy_feed_rate, dt);
    if (!z_done || !xy_done)
        return;
    zoff = 0.0;
    if (offsets_active)
        return;
    probe_testing = 0;
    plasmac_goto(__comp_inst, stop_type_out == PM_STOP_PAUSE ? PM_PAUSED : PM_IDLE);
}

/* TORCH_PULSE: torch on for torch-pulse-time. */
static void plasmac_torch_pulse(struct __comp_state *__comp_inst, double dt)
{
    torch_on = 1;
    timer += dt;
    if (!(timer < torch_pulse_time)) {  /* a NaN time ends the pulse at once */
        torch_on = 0;
        plasmac_goto(__comp_inst, PM_IDLE);
    }
}

/* paused-motion-speed clamped to -1..1. */
static double plasmac_paused_speed(struct __comp_state *__comp_inst)
{
    if (paused_motion_speed > 1.0)
        return 1.0;
    if (paused_motion_speed < -1.0)
        return -1.0;
    return paused_motion_speed;
}

/* PAUSED: wait for resume (restart the cut), stop, or a consumable change. */
static void plasmac_paused(struct __comp_state *__comp_inst, double dt)
{
    (void)dt;
    if (program_is_paused)
        seen_paused = 1;
    if (!seen_paused)
        return;
    if (program_is_paused && consumable_change) {
        plasmac_goto(__comp_inst, PM_CONSUMABLE_CHANGE_ON);
    } else if (program_is_paused && cut_recovery) {
        plasmac_goto(__comp_inst, PM_CUT_RECOVERY);
    } else if (program_is_paused && laser_recovery_start) {
        plasmac_goto(__comp_inst, PM_LASER_RECOVERY);
    } else if (program_is_paused && paused_motion_speed != 0.0) {
        program_resume = 1;
        adaptive_feed = plasmac_paused_speed(__comp_inst);
        plasmac_goto(__comp_inst, PM_PAUSED_MOTION);
    } else if (program_is_idle && !program_is_paused) {
        stop_type_out = PM_STOP_NONE;
        plasmac_goto(__comp_inst, PM_IDLE);
    } else if (program_is_running && !program_is_paused) {
        stop_type_out = PM_STOP_NONE;
        if (tool != PM_TOOL_SCRIBE && plasmac_request(__comp_inst) &&
            plasmac_torch_allowed(__comp_inst))
            plasmac_start_cut(__comp_inst);
        else
            plasmac_goto(__comp_inst, PM_IDLE);
    }
}

/* CONSUMABLE_CHANGE_ON: move X/Y to the change position until the request ends. */
static void plasmac_change_on(struct __comp_state *__comp_inst, double dt)
{
    if (!consumable_change || program_is_idle)
        plasmac_goto(__comp_inst, PM_CONSUMABLE_CHANGE_OFF);
    else
        plasmac_move_xy(__comp_inst, x_offset, y_offset, xy_feed_rate, dt);
}

/* CONSUMABLE_CHANGE_OFF: move X/Y back, then wait in the pause again. */
static void plasmac_change_off(struct __comp_state *__comp_inst, double dt)
{
    if (plasmac_move_xy(__comp_inst, 0.0, 0.0, xy_feed_rate, dt) && !offsets_active)
        plasmac_goto(__comp_inst, PM_PAUSED);
}

/* PROBE_TEST: hold at pierce height until the probe test request ends. */
static void plasmac_probe_test(struct __comp_state *__comp_inst, double dt)
{
    plasmac_move_z(__comp_inst, plasmac_above_zero(__comp_inst, pierce_height),
                   setup_feed_rate, dt);
    if (!plasmac_probe_test_request(__comp_inst))
        plasmac_goto(__comp_inst, PM_MAX_HEIGHT);
}

/* PAUSED_MOTION: run along the path with the torch off at paused-motion-speed, pause at 0. */
static void plasmac_paused_motion(struct __comp_state *__comp_inst, double dt)
{
    double speed = plasmac_paused_speed(__comp_inst);
    (void)dt;
    adaptive_feed = speed;
    if (program_is_idle && !program_is_paused && !program_resume) {
        adaptive_feed = 1.0;
        stop_type_out = PM_STOP_NONE;
        plasmac_goto(__comp_inst, PM_IDLE);
    } else if (speed == 0.0) {
        program_resume = 0;
        program_pause = 1;
        seen_paused = 0;
        adaptive_feed = 1.0;
        plasmac_goto(__comp_inst, PM_PAUSED);
    }
}
