/* plasmac_abort.h: what stops a plasmac cut: offset limits, sensors, a lost arc, the program
 * pausing or stopping, M5, and low arc voltage under THC (included by plasmac.comp). */

/* Enter a state. */
static void pm_goto(struct __comp_state *__comp_inst, int next)
{
    state_out = next;
}

/* Torch off, the program paused (when it runs), stop type PAUSE, then raise the torch. */
static void pm_abort(struct __comp_state *__comp_inst)
{
    torch_on = 0;
    if (!program_is_idle) program_pause = 1;
    stop_type_out = PM_STOP_PAUSE;
    pm_goto(__comp_inst, PM_MAX_HEIGHT);
}

/* Offset limit violation: once until motion clears eoffset-limited. */
static void pm_offset_limit(struct __comp_state *__comp_inst)
{
    char line[80];
    if (!offsets_limited) {
        limit_latched = 0;
        return;
    }
    if (!offsets_active || limit_latched) return;
    limit_latched = 1;
    probe_inhibit = 1;
    rtapi_snprintf(line, sizeof(line), "Offset limit violation (state: %s)",
                   state_out >= 0 && state_out < PM_STATES ? pm_state_names[state_out] : "?");
    pm_pause_msg(line);
    pm_abort(__comp_inst);
}

/* The name of the sensor that is active (breakaway first). */
static const char *pm_sensor_name(struct __comp_state *__comp_inst)
{
    if (breakaway) return "breakaway switch activated";
    if (float_switch) return "float switch activated";
    return "ohmic probe activated";
}

/* The program ended with a cut started: stop, then finish the cut or the change in progress. */
static void pm_program_ended(struct __comp_state *__comp_inst)
{
    cut_started = 0;
    stop_type_out = PM_STOP_STOP;
    program_stop = 1;
    if (consumable_changing) pm_goto(__comp_inst, PM_CONSUMABLE_CHANGE_OFF);
    else if (cut_recovering) pm_goto(__comp_inst, PM_CUT_RECOVERY_OFF);
    else if (torch_on && pause_at_end > 0) pm_goto(__comp_inst, PM_PAUSE_AT_END);
    else {
        torch_on = 0;
        pm_goto(__comp_inst, PM_MAX_HEIGHT);
    }
}

/* M5 during a cut: wait for the next cut at the end point. */
static void pm_tool_off(struct __comp_state *__comp_inst)
{
    if (!job) {
        torch_on = 0;
        program_stop = 1;
        pm_goto(__comp_inst, PM_MAX_HEIGHT);
        return;
    }
    stop_type_out = PM_STOP_WAIT;
    if (pause_at_end <= 0) torch_on = 0;
    end_x = axis_x_position;
    end_y = axis_y_position;
    timer = pause_at_end;
    pm_goto(__comp_inst, PM_PAUSE_AT_END);
}

/* TRUE while the arc is needed and supervised. */
static int pm_arc_supervised(struct __comp_state *__comp_inst)
{
    return torch_enable && !mesh_enable && !ignore_arc_ok_0 && !ignore_arc_ok_1 && !laser_mode;
}

/* Checks during states 1..12 of a started cut. */
static void pm_cut_checks(struct __comp_state *__comp_inst)
{
    int s = state_out, after_arc = s > PM_ARC_OK && s <= PM_CUT_MODE_2;
    if (program_is_paused) {
        pm_abort(__comp_inst);
    } else if (tool == PM_TOOL_EMPTY) {
        pm_tool_off(__comp_inst);
    } else if (breakaway || (after_arc && !tube_cut && (float_switch || ohmic_probe))) {
        pm_pause_msg(pm_sensor_name(__comp_inst));
        pm_abort(__comp_inst);
    } else if (after_arc && pm_arc_supervised(__comp_inst) && !arc_ok_out && tool == PM_TOOL_CUTTING) {
        pm_pause_msg("valid arc lost");
        pm_abort(__comp_inst);
    }
}

/* Step 10: sensors between cuts of a running job, the end of the program, and a started cut's checks. */
static void pm_abort_checks(struct __comp_state *__comp_inst)
{
    int s = state_out;
    if (s == PM_IDLE && job && sensor_active && !program_is_idle && !tube_cut
        && stop_type_out != PM_STOP_PAUSE) {
        pm_pause_msg(pm_sensor_name(__comp_inst));
        pm_abort(__comp_inst);
    } else if (job && program_is_idle && cut_started) {
        pm_program_ended(__comp_inst);
    } else if (cut_started && s >= PM_PROBE_HEIGHT && s <= PM_CUT_MODE_2 && stop_type_out == PM_STOP_NONE
               && !probe_test) {
        pm_cut_checks(__comp_inst);
    }
}

/* Step 12: the arc voltage fell below low-cut-volts while THC was active. */
static void pm_low_volts(struct __comp_state *__comp_inst)
{
    char line[80];
    if (low_cut_volts == 0 || !thc_active || arc_voltage_out >= low_cut_volts) return;
    pm_msg("arc voltage fell below safe level while THC active");
    rtapi_snprintf(line, sizeof(line), "target voltage = %0.2fV", target_volts);
    pm_msg(line);
    rtapi_snprintf(line, sizeof(line), "limit voltage = %dV", low_cut_volts);
    pm_msg(line);
    rtapi_snprintf(line, sizeof(line), "arc voltage = %0.2fV", arc_voltage_out);
    pm_pause_msg(line);
    pm_abort(__comp_inst);
}
