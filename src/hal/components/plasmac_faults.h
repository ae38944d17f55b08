/* plasmac_faults.h: plasmac state handler table and the faults that override it (included by plasmac.comp). */

/* The handler of each state, indexed by state number. */
static const plasmac_handler_t plasmac_handlers[PM_STATE_COUNT] = {
    [PM_IDLE] = plasmac_idle,
    [PM_PROBE_HEIGHT] = plasmac_probe_height,
    [PM_PROBE_DOWN] = plasmac_probe_down,
    [PM_PROBE_UP] = plasmac_probe_up,
    [PM_ZERO_HEIGHT] = plasmac_zero_height,
    [PM_PIERCE_HEIGHT] = plasmac_pierce_height,
    [PM_TORCH_ON] = plasmac_torch_on,
    [PM_ARC_OK] = plasmac_arc_ok,
    [PM_PIERCE_DELAY] = plasmac_pierce_delay,
    [PM_PUDDLE_JUMP] = plasmac_puddle_jump,
    [PM_CUT_HEIGHT] = plasmac_cut_height,
    [PM_CUT_MODE_01] = plasmac_cut_mode_01,
    [PM_CUT_MODE_2] = plasmac_cut_mode_2,
    [PM_END_CUT] = plasmac_end_cut,
    [PM_SAFE_HEIGHT] = plasmac_safe_height,
    [PM_MAX_HEIGHT] = plasmac_max_height,
    [PM_TORCH_PULSE] = plasmac_torch_pulse,
    [PM_PAUSED] = plasmac_paused,
    [PM_PROBE_TEST] = plasmac_probe_test,
    [PM_CONSUMABLE_CHANGE_ON] = plasmac_change_on,
    [PM_CONSUMABLE_CHANGE_OFF] = plasmac_change_off,
    [PM_PAUSED_MOTION] = plasmac_paused_motion,
    [PM_SCRIBE_ARM] = plasmac_scribe_arm_state,
    [PM_SCRIBE_ON] = plasmac_scribe_on_state,
    [PM_SCRIBING] = plasmac_scribing,
    [PM_SPOTTING] = plasmac_spotting,
    [PM_OHMIC_RETRY] = plasmac_ohmic_retry,
    [PM_OFFSET_PROBE] = plasmac_offset_probe,
    [PM_OFFSET_RETURN] = plasmac_offset_return,
    [PM_RECOVER_RETURN] = plasmac_recover_return,
    [PM_CUT_RECOVERY] = plasmac_cut_recovery,
    [PM_LASER_RECOVERY] = plasmac_laser_recovery,
};

/* TRUE in the states of a cut or spot, from probing to cutting. */
static int plasmac_in_cut(struct __comp_state *__comp_inst)
{
    int cut_state = (state >= PM_PROBE_HEIGHT && state <= PM_CUT_MODE_2) ||
                    state == PM_SPOTTING || state == PM_OHMIC_RETRY ||
                    state == PM_OFFSET_PROBE || state == PM_OFFSET_RETURN ||
                    state == PM_RECOVER_RETURN;
    return cut_state && !probe_testing;
}

/* TRUE while the torch is (or is about to be) lit in a cut or spot. */
static int plasmac_torch_state(struct __comp_state *__comp_inst)
{
    return (state >= PM_TORCH_ON && state <= PM_CUT_MODE_2) || state == PM_SPOTTING ||
           state == PM_RECOVER_RETURN;
}

/* Machine off: torch off, offsets cleared at once, back to IDLE. */
static void plasmac_machine_off(struct __comp_state *__comp_inst)
{
    plasmac_leave_cut(__comp_inst);
    zoff = xoff = yoff = 0.0;
    probe_testing = 0;
    laser_recovery_state = PM_LASER_NONE;
    stop_type_out = PM_STOP_NONE;
    plasmac_goto(__comp_inst, PM_IDLE);
}

/* TRUE while the torch is lit and must have a valid arc. */
static int plasmac_arc_required(struct __comp_state *__comp_inst)
{
    return ((state >= PM_PIERCE_DELAY && state <= PM_CUT_MODE_2) || state == PM_RECOVER_RETURN) &&
           !plasmac_ignore_arc(__comp_inst);
}

/* TRUE in the states where a closed float switch means a collision (after probing). */
static int plasmac_float_faults(struct __comp_state *__comp_inst)
{
    return (state >= PM_PIERCE_HEIGHT && state <= PM_CUT_MODE_2) || state == PM_SPOTTING ||
           state == PM_RECOVER_RETURN;
}

/* TRUE once the arc has been lost for longer than arc-lost-delay. */
static int plasmac_arc_lost(struct __comp_state *__comp_inst, double dt)
{
    if (!plasmac_arc_required(__comp_inst) || arc_ok_now) {
        lost_timer = 0.0;
        return 0;
    }
    lost_timer += dt;
    return !(lost_timer < arc_lost_delay);  /* a NaN delay counts as expired: arc lost */
}

/* External estop: everything off, offsets back to 0 with a stop; 1 when the handler must not run. */
static int plasmac_estop(struct __comp_state *__comp_inst)
{
    int at_rest = state == PM_IDLE && zoff == 0.0 && xoff == 0.0 && yoff == 0.0;
    plasmac_leave_cut(__comp_inst);
    probe_testing = 0;
    laser_recovery_state = PM_LASER_NONE;
    if (state == PM_MAX_HEIGHT)
        return 0;
    if (!at_rest)
        plasmac_abort(__comp_inst, PM_ERR_EXTERNAL_ESTOP, PM_STOP_STOP);
    return 1;
}

/* Faults of a running cut or spot; 1 when one acted. */
static int plasmac_cut_faults(struct __comp_state *__comp_inst, double dt)
{
    if (breakaway)
        plasmac_abort(__comp_inst, PM_ERR_BREAKAWAY, PM_STOP_PAUSE);
    else if (float_switch && plasmac_float_faults(__comp_inst))
        plasmac_abort(__comp_inst, PM_ERR_FLOAT_SWITCH, PM_STOP_PAUSE);
    else if (program_is_paused)
        plasmac_abort(__comp_inst, PM_ERR_NONE, PM_STOP_PAUSE);
    else if (program_is_idle)
        plasmac_abort(__comp_inst, PM_ERR_NONE, PM_STOP_STOP);
    else if (!plasmac_request(__comp_inst) || cutting_stop ||
             (torch_off && plasmac_torch_state(__comp_inst))) {
        plasmac_leave_cut(__comp_inst);
        plasmac_goto(__comp_inst, PM_END_CUT);
    }
    else if (plasmac_arc_lost(__comp_inst, dt))
        plasmac_abort(__comp_inst, PM_ERR_ARC_LOST, PM_STOP_PAUSE);
    else
        return 0;
    return 1;
}

/* Faults and operator actions that override the state handler; 1 when one acted. */
static int plasmac_faults(struct __comp_state *__comp_inst, double dt)
{
    if (!machine_is_on) {
        plasmac_machine_off(__comp_inst);
        return 1;
    }
    if (external_estop)
        return plasmac_estop(__comp_inst);
    if (probe_testing && (state <= PM_ZERO_HEIGHT || state == PM_OHMIC_RETRY) && breakaway) {
        plasmac_probe_failed(__comp_inst);
        return 1;
    }
    if (!plasmac_in_cut(__comp_inst))
        return 0;
    return plasmac_cut_faults(__comp_inst, dt);
}
