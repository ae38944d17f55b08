/* plasmac_cut.h: plasmac from pierce height to cut height: PIERCE_HEIGHT, TORCH_ON, ARC_OK,
 * PIERCE_DELAY, PUDDLE_JUMP, CUT_HEIGHT (included by plasmac.comp). */

/* PIERCE_HEIGHT: check the heights, move to pierce height, then test, dry run or start the torch. */
static void pm_pierce_height(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    int cutting = tool == PM_TOOL_CUTTING && !probe_test;
    if (pierce_height == 0 || (cutting && (cut_height == 0 || (!use_auto_volts && cut_volts == 0 && mode < 2)))) {
        pm_msg("invalid pierce height.");
        pm_msg("or invalid cut height.");
        pm_msg("or invalid cut volts.");
        pm_msg("program is paused.");
        pm_abort(__comp_inst);
        return;
    }
    if (!pm_z_move(__comp_inst, pierce_t, pm_setup_speed(__comp_inst))) return;
    if (probe_test) {
        pm_goto(__comp_inst, PM_PROBE_TEST);
    } else if (!torch_enable) {
        timer = pierce_delay + cut_height_delay;
        pierce_dist = 0;
        pm_goto(__comp_inst, PM_PIERCE_DELAY);
    } else {
        restart_timer = 0;
        pm_goto(__comp_inst, PM_TORCH_ON);
    }
}

/* No arc after arc-max-starts starts: reported once; a manual cut is stopped, a program paused. */
static void pm_no_arc(struct __comp_state *__comp_inst)
{
    char line[80];
    if (!no_arc_told) {
        no_arc_told = 1;
        rtapi_snprintf(line, sizeof(line), "no arc detected after %d start attempts", arc_max_starts);
        pm_msg(line);
        pm_msg(job ? "program is paused." : "manual cut is stopped.");
    }
    torch_on = 0;
    if (job) {
        pm_abort(__comp_inst);
    } else {
        cutting_stop = 1;
        pm_goto(__comp_inst, PM_MAX_HEIGHT);
    }
}

/* TORCH_ON: after the restart delay switch the torch on and wait for the arc. */
static void pm_torch_on_state(struct __comp_state *__comp_inst, double t)
{
    if (starts >= arc_max_starts) {
        pm_no_arc(__comp_inst);
        return;
    }
    if (restart_timer > 0) {
        restart_timer -= t;
        return;
    }
    no_arc_told = 0;
    if (torch_enable) torch_on = 1;
    pierce_count++;
    starts++;
    fail_timer = arc_fail_delay;
    ring_idx = ring_n = 0;
    spot_started = 0;
    pm_goto(__comp_inst, PM_ARC_OK);
}

/* Spotting: once the voltage reaches the threshold keep the torch on spotting-time milliseconds. */
static int pm_spotting(struct __comp_state *__comp_inst, double t)
{
    if (!spot_started && arc_voltage_out >= spotting_threshold) {
        spot_started = 1;
        spot_timer = spotting_time / 1000.0;
    }
    if (!spot_started) return 0;
    spot_timer -= t;
    if (spot_timer > 0) return 1;
    torch_on = 0;
    starts = 0;
    stop_type_out = PM_STOP_WAIT;
    pm_goto(__comp_inst, PM_SAFE_HEIGHT);
    return 1;
}

/* ARC_OK: spotting, a failed start, or a valid arc starting the pierce delay. */
static void pm_arc_ok_state(struct __comp_state *__comp_inst, double t)
{
    if (tool == PM_TOOL_SPOTTING && pm_spotting(__comp_inst, t)) return;
    if (arc_ok_out || ignore_arc_ok_0 || ignore_arc_ok_1 || mesh_enable || laser_mode) {
        starts = 0;
        timer = pierce_delay + cut_height_delay;
        pierce_dist = 0;
        pierce_px = axis_x_position;
        pierce_py = axis_y_position;
        pm_goto(__comp_inst, PM_PIERCE_DELAY);
        return;
    }
    fail_timer -= t;
    if (fail_timer > 0) return;
    torch_on = 0;
    restart_timer = restart_delay;
    pm_goto(__comp_inst, PM_TORCH_ON);
}

/* Ramp pierce: XY at gouge speed, then creep speed, as a fraction of the cut feed rate. */
static void pm_ramp_feed(struct __comp_state *__comp_inst)
{
    double pct;
    pierce_dist += hypot(axis_x_position - pierce_px, axis_y_position - pierce_py);
    pierce_px = axis_x_position;
    pierce_py = axis_y_position;
    pct = pierce_dist < gouge_speed_distance ? gouge_speed
          : pierce_dist < gouge_speed_distance + creep_speed_distance ? creep_speed : 100.0;
    adaptive_feed = pct / 100.0;
    requested_feed_rate = cut_feed_rate * adaptive_feed;
}

/* Ramp pierce: after pierce-motion-delay percent of the pierce delay, Z ramps to pierce-end-height. */
static void pm_ramp_z(struct __comp_state *__comp_inst)
{
    double pmd = pierce_motion_delay / 100.0, run = pierce_delay * (1.0 - pmd);
    if (pierce_delay + cut_height_delay - timer < pierce_delay * pmd || run <= 0) return;
    int v = pm_counts((pierce_height - pierce_end_height) / run * 60.0 * vs);
    pm_z_move(__comp_inst, pierce_end_t, v < 1 ? 1 : v);
}

/* PIERCE_DELAY: hold (or pierce with motion), then puddle jump or cut height. */
static void pm_pierce_delay(struct __comp_state *__comp_inst, double t)
{
    int moving = pierce_type == 1 || pierce_type == 2;
    double pmd = pierce_motion_delay / 100.0;
    feed_hold = !moving || (pierce_delay + cut_height_delay - timer < pierce_delay * pmd);
    if (pierce_type == 2 && !feed_hold) {
        pm_ramp_feed(__comp_inst);
        pm_ramp_z(__comp_inst);
    }
    timer -= t;
    if (timer > 0) return;
    if (tube_cut) {
        thc_timer = thc_delay;
        pm_goto(__comp_inst, PM_CUT_MODE_01);
    } else if (puddle_jump_height > 0 && puddle_jump_height != 100 && !recovering) {
        timer = puddle_jump_delay;
        pm_goto(__comp_inst, PM_PUDDLE_JUMP);
    } else {
        pm_goto(__comp_inst, PM_CUT_HEIGHT);
    }
}

/* PUDDLE_JUMP: motion runs at the puddle jump height for puddle-jump-delay. */
static void pm_puddle_jump(struct __comp_state *__comp_inst, double t)
{
    feed_hold = 0;
    if (!pm_z_move(__comp_inst, puddle_t, pm_setup_speed(__comp_inst))) return;
    timer -= t;
    if (timer <= 0) pm_goto(__comp_inst, PM_CUT_HEIGHT);
}

/* CUT_HEIGHT: to cut height, then cut (or return from a recovery offset first). */
static void pm_cut_height(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (!pm_z_move(__comp_inst, cut_t, pm_setup_speed(__comp_inst))) return;
    adaptive_feed = 1;
    if (recovering) {
        pm_goto(__comp_inst, PM_CUT_RECOVERY_OFF);
        return;
    }
    feed_hold = 0;
    thc_timer = thc_delay;
    auto_sum = 0;
    auto_n = 0;
    override_prev = height_override;
    pm_goto(__comp_inst, mode < 2 ? PM_CUT_MODE_01 : PM_CUT_MODE_2);
}
