/* plasmac_cycle.h: plasmac's period: LinuxCNC's steps before the state machine, the machine-off
 * reset, the state handler table and the state-change report (included by plasmac.comp). */

/* Step 8: THC allowed and active. */
static void pm_thc_flags(struct __comp_state *__comp_inst)
{
    int cutting = state_out == PM_CUT_MODE_01 || state_out == PM_CUT_MODE_2;
    int source = mode < 2 ? target_volts != 0 : arc_ok_out;
    thc_enabled = thc_enable && !thc_disable && !mesh_enable && !ignore_arc_ok_0 && !ignore_arc_ok_1
                  && lost_timer > arc_lost_delay - 1e-6;
    thc_active = cutting && source && thc_enabled && !cornerlock_is_locked && !voidlock_is_locked;
}

/* Step 9: adaptive feed from feed-reduction while cutting, 1 elsewhere (not while moving paused). */
static void pm_adaptive_feed(struct __comp_state *__comp_inst)
{
    int cutting = state_out == PM_CUT_MODE_01 || state_out == PM_CUT_MODE_2;
    if (state_out == PM_PAUSED_MOTION || state_out == PM_PIERCE_DELAY) return;
    if (cutting && feed_reduction > 0 && feed_reduction < 100) adaptive_feed = feed_reduction / 100.0;
    else adaptive_feed = 1;
}

/* An infinite or NaN arc voltage is reported once a second and stops the period (0). */
static int pm_volts_valid(struct __comp_state *__comp_inst, double t)
{
    if (arc_voltage_in - arc_voltage_in == 0) {
        bad_volts_timer = 0;
        return 1;
    }
    if (bad_volts_timer <= 0) {
        pm_msg("invalid arc-voltage-in");
        bad_volts_timer = 1.0;
    }
    bad_volts_timer -= t;
    return 0;
}

/* Steps 1 to 17 of LinuxCNC's period; 0 when the period stops at an invalid arc voltage. */
static int pm_before(struct __comp_state *__comp_inst, double t)
{
    rtapi_set_msg_level(debug_print ? RTAPI_MSG_INFO : RTAPI_MSG_ERR);
    if (!pm_volts_valid(__comp_inst, t)) return 0;
    pm_scaling(__comp_inst, t);
    tool = pm_active_tool(__comp_inst);
    sensor_active = breakaway || float_switch || ohmic_probe;
    probe_out = float_switch && tube_cut && state_out == PM_IDLE;
    current_feed_rate = current_velocity * 60.0;
    pm_offset_limit(__comp_inst);
    z_height = has_zero ? z_offset_current - zero * offset_scale : axis_z_position - axis_z_min_limit;
    if (torch_off) torch_on = 0;
    pm_thc_flags(__comp_inst);
    pm_adaptive_feed(__comp_inst);
    pm_abort_checks(__comp_inst);
    pm_arc_voltage(__comp_inst, t);
    pm_low_volts(__comp_inst);
    pm_ohmic_sense(__comp_inst);
    pm_arc_ok(__comp_inst, t);
    pm_program_status(__comp_inst, t);
    jog_inhibit = sensor_active && program_is_idle
                  && !(override_jog || state_out == PM_PROBE_DOWN || state_out == PM_PROBE_UP);
    pm_deploy(__comp_inst);
    return 1;
}

/* Step 18: machine off: every offset 0, torch and program pulses off, back to IDLE. */
static void pm_machine_off(struct __comp_state *__comp_inst)
{
    x_offset_counts = y_offset_counts = z_offset_counts = 0;
    stop_type_out = PM_STOP_NONE;
    probe_required = 1;
    program_pause = program_resume = program_run = program_stop = 0;
    torch_on = 0;
    cut_started = 0;
    recovering = 0;
    cut_recovering = consumable_changing = 0;
    laser_x = laser_y = 0;
    state_out = PM_IDLE;
}

/* The DEBUG state (never entered on purpose). */
static void pm_debug_state(struct __comp_state *__comp_inst, double t)
{
    (void)t;
    (void)__comp_inst;
    pm_msg("We should never end up here...");
}

/* The handler of each state, in state-out order. */
typedef void (*pm_handler_t)(struct __comp_state *, double);
static const pm_handler_t pm_handlers[PM_STATES] = {
    pm_idle, pm_probe_height, pm_probe_down, pm_probe_up, pm_zero_height, pm_pierce_height, pm_torch_on_state,
    pm_arc_ok_state, pm_pierce_delay, pm_puddle_jump, pm_cut_height, pm_cut_mode_01, pm_cut_mode_2,
    pm_pause_at_end, pm_safe_height, pm_max_height, pm_end_cut, pm_end_job, pm_torch_pulse, pm_paused_motion,
    pm_ohmic_test_state, pm_probe_test_state, pm_scribing, pm_consumable_on, pm_consumable_off, pm_recovery_on,
    pm_recovery_off, pm_debug_state,
};

/* Run the handler of the present state. */
static void pm_run_state(struct __comp_state *__comp_inst, double t)
{
    if (state_out < 0 || state_out >= PM_STATES) state_out = PM_DEBUG;
    pm_handlers[state_out](__comp_inst, t);
}

/* With debug-print, each state change is printed (END_JOB adds an empty line). */
static void pm_after(struct __comp_state *__comp_inst)
{
    if (state_out == last_state) return;
    last_state = state_out;
    if (!debug_print) return;
    rtapi_print_msg(RTAPI_MSG_INFO, "%s\n",
                    state_out >= 0 && state_out < PM_STATES ? pm_state_names[state_out] : "DEBUG");
    if (state_out == PM_END_JOB) rtapi_print_msg(RTAPI_MSG_INFO, "\n");
}
