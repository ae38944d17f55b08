/* plasmac_end.h: plasmac after a cut and the short jobs: PAUSE_AT_END, SAFE_HEIGHT, MAX_HEIGHT,
 * END_CUT, END_JOB, TORCHPULSE, OHMIC_TEST, PROBE_TEST, SCRIBING (included by plasmac.comp). */

/* PAUSE_AT_END: keep going pause-at-end seconds, then torch off and up. */
static void pm_pause_at_end(struct __comp_state *__comp_inst, double t)
{
    timer -= t;
    if (timer > 0) return;
    torch_on = 0;
    pm_goto(__comp_inst, program_is_idle ? PM_MAX_HEIGHT : PM_SAFE_HEIGHT);
}

/* SAFE_HEIGHT: torch off, motion held, up to the safe height; release motion when waiting for the next cut. */
static void pm_safe_height(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    torch_on = 0;
    feed_hold = 1;
    if (!pm_z_move(__comp_inst, safe_t, pm_setup_speed(__comp_inst))) return;
    if (stop_type_out == PM_STOP_WAIT) {
        feed_hold = 0;
        stop_type_out = PM_STOP_NONE;
    }
    pm_goto(__comp_inst, PM_END_CUT);
}

/* MAX_HEIGHT: torch off, motion held, Z offset back to 0; then a consumable change, a recovery or the end. */
static void pm_max_height(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    torch_on = 0;
    feed_hold = 1;
    cornerlock_is_locked = 0;
    if (!pm_z_move(__comp_inst, 0, pm_setup_speed(__comp_inst))) return;
    if (consumable_change && program_is_paused) {
        pm_goto(__comp_inst, PM_CONSUMABLE_CHANGE_ON);
    } else if (cut_recovery && stop_type_out != PM_STOP_STOP) {
        pm_goto(__comp_inst, PM_CUT_RECOVERY_ON);
    } else if (offset_probing && !pm_xy_move(__comp_inst, pm_home_x(__comp_inst), pm_home_y(__comp_inst),
                                             pm_speed(__comp_inst, offset_feed_rate))) {
        return;
    } else {
        offset_probing = 0;
        pm_goto(__comp_inst, PM_END_CUT);
    }
}

/* END_CUT: the cut's flags off; the job ends with the program. */
static void pm_end_cut(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    target_volts = 0;
    cornerlock_is_locked = voidlock_is_locked = 0;
    led_up = led_down = 0;
    ohmic_enable = 0;
    probe_test_error = 0;
    cutting_stop = 0;
    starts = 0;
    cut_started = 0;
    pm_goto(__comp_inst, program_is_idle ? PM_END_JOB : PM_IDLE);
}

/* END_JOB: offsets back to 0 with the program idle, then the per-job state is reset. */
static void pm_end_job(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    job = 0;
    program_run = 0;
    paused_motion = 0;
    adaptive_feed = 1;
    if (program_is_idle) {
        int z = pm_z_move(__comp_inst, 0, pm_setup_speed(__comp_inst));
        int xy = pm_xy_move(__comp_inst, 0, 0, pm_setup_speed(__comp_inst));
        if (!z || !xy || offsets_active) return;
    }
    stop_type_out = PM_STOP_NONE;
    feed_hold = 0;
    first_cut = probe_required = 1;
    has_zero = 0;
    thc_was_active = 0;
    safe_height_is_limited = 0;
    recovering = 0;
    cut_recovering = 0;
    consumable_changing = 0;
    laser_x = laser_y = 0;
    laser_recovery_state = PM_LASER_OFF;
    pm_goto(__comp_inst, PM_IDLE);
}

/* TORCHPULSE: torch on for torch-pulse-time (longer while held); abort or torch disabled ends it. */
static void pm_torch_pulse(struct __comp_state *__comp_inst, double t)
{
    if (torch_enable && !torch_pulse_abort && (timer > 0 || torch_pulse_hold)) {
        torch_on = 1;
        timer -= t;
        return;
    }
    torch_on = 0;
    if (torch_pulse_start && !torch_pulse_abort && torch_enable) return;   /* wait for the release */
    pm_goto(__comp_inst, pulse_recovery ? PM_CUT_RECOVERY_ON : PM_IDLE);
}

/* OHMIC_TEST: the ohmic circuit powered while the test input is held. */
static void pm_ohmic_test_state(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    ohmic_enable = 1;
    if (ohmic_test) return;
    ohmic_enable = 0;
    pm_goto(__comp_inst, PM_IDLE);
}

/* PROBE_TEST: hold at pierce height while the test input is held, then every offset back to 0. */
static void pm_probe_test_state(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    if (probe_test) return;
    int z = pm_z_move(__comp_inst, 0, pm_setup_speed(__comp_inst));
    int xy = pm_xy_move(__comp_inst, 0, 0, pm_setup_speed(__comp_inst));
    if (z && xy) {
        feed_hold = 0;
        pm_goto(__comp_inst, PM_END_CUT);
    }
}

/* SCRIBING: arm, wait, on, wait, release motion; a pause drops the scribe and restarts the delays. */
static void pm_scribing(struct __comp_state *__comp_inst, double t)
{
    if (tool != PM_TOOL_SCRIBE) {
        scribe_arm = scribe_on = 0;
        feed_hold = 0;
        pm_goto(__comp_inst, PM_IDLE);
        return;
    }
    if (program_is_paused) {
        scribe_arm = scribe_on = 0;
        scribe_phase = 0;
        timer = scribe_arm_delay;
        return;
    }
    scribe_arm = 1;
    if (scribe_phase == 2) return;
    feed_hold = 1;
    if ((timer -= t) > 0) return;
    if (scribe_phase == 0) {
        scribe_on = 1;
        scribe_phase = 1;
        timer = scribe_on_delay;
    } else {
        feed_hold = 0;
        scribe_phase = 2;
    }
}
