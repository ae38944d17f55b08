/* plasmac_io.h: plasmac's per-period sensing: scaling, tool, arc voltage, arc OK, ohmic sense,
 * program status and statistics (included by plasmac.comp after its pin macros). */

/* An error message line. */
static void pm_msg(const char *text)
{
    rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", text);
}

/* A message followed by "program is paused.". */
static void pm_pause_msg(const char *text)
{
    pm_msg(text);
    pm_msg("program is paused.");
}

/* machine units per mm, 1 until configured. */
static double pm_upm(struct __comp_state *__comp_inst)
{
    return units_per_mm > 0 ? units_per_mm : 1.0;
}

/* Machine units as offset counts. */
static int pm_to_counts(struct __comp_state *__comp_inst, double units)
{
    return offset_scale > 0 ? pm_counts(units / offset_scale) : 0;
}

/* A feed rate (machine units per minute) as counts per period, truncated. */
static int pm_speed(struct __comp_state *__comp_inst, double feed)
{
    return pm_counts(feed * vs);
}

/* Resolution, offset scale and the counts-per-feed factor. */
static void pm_scaling(struct __comp_state *__comp_inst, double t)
{
    int res = pm_clampi(resolution, 1, 1000);
    double upm = pm_upm(__comp_inst);
    offset_res = upm == 1.0 ? res : 10.0 * res;
    offset_scale = upm * t / res;
    vs = res / upm / 60.0;
}

/* The active tool: cutting, scribe or spotting (multi-tool) or none. */
static int pm_active_tool(struct __comp_state *__comp_inst)
{
    if (cutting_start && !dry_run) return PM_TOOL_CUTTING;
    if (multi_tool && scribe_start && !spotting_start) return PM_TOOL_SCRIBE;
    if (multi_tool && spotting_start && !scribe_start) return PM_TOOL_SPOTTING;
    return PM_TOOL_EMPTY;
}

/* Low-pass the arc voltage and publish it with offset, scale and zero window. */
static void pm_arc_voltage(struct __comp_state *__comp_inst, double t)
{
    double f = fabs(lowpass_frequency), v;
    if (lowpass_frequency != 0)
        raw_volts += (arc_voltage_in - raw_volts) * (1.0 - exp(-2.0 * M_PI * f * t));
    else
        raw_volts = arc_voltage_in;
    v = round((fabs(raw_volts) - arc_voltage_offset) * fabs(arc_voltage_scale) * 1000.0) / 1000.0;
    if (v > -zero_window && v < zero_window) v = 0;
    arc_voltage_out = v;
}

/* Mode 0: are the last n ring samples within threshold of v? */
static int pm_ring_near(struct __comp_state *__comp_inst, int n, double v, double thr)
{
    if (ring_n < n) return 0;
    for (int k = 1; k <= n; k++)
        if (fabs(ring[(ring_idx - k + PM_RING) % PM_RING] - v) > thr) return 0;
    return 1;
}

/* Mode 0: are all the last n ring samples further than threshold from target-volts? */
static int pm_ring_far(struct __comp_state *__comp_inst, int n, double thr)
{
    int m = n < ring_n ? n : ring_n;
    for (int k = 1; k <= m; k++)
        if (fabs(ring[(ring_idx - k + PM_RING) % PM_RING] - target_volts) <= thr) return 0;
    return 1;
}

/* Mode 0 arc OK from the voltage window and the agreement of the last samples. */
static void pm_arc_ok_volts(struct __comp_state *__comp_inst, double t)
{
    int n = pm_clampi(ok_sample_counts, 1, 1000);
    double v = arc_voltage_out;
    int in_window = v >= arc_ok_low && v <= arc_ok_high;
    if (!arc_ok_out) {
        if (in_window && pm_ring_near(__comp_inst, n, v, ok_sample_threshold)) {
            arc_ok_out = 1;
            lost_timer = arc_lost_delay;
        }
        return;
    }
    if (in_window || !pm_ring_far(__comp_inst, n, ok_sample_threshold)) {
        lost_timer = arc_lost_delay;
        return;
    }
    lost_timer -= t;
    if (lost_timer <= 0) arc_ok_out = 0;
}

/* Arc OK and torch time while the torch is on; reset when it is off. */
static void pm_arc_ok(struct __comp_state *__comp_inst, double t)
{
    if (!torch_on) {
        arc_ok_out = 0;
        lost_timer = arc_lost_delay;
        return;
    }
    torch_time += t;
    ring[ring_idx] = arc_voltage_out;
    ring_idx = (ring_idx + 1) % PM_RING;
    if (ring_n < PM_RING) ring_n++;
    if (mode == 0) {
        pm_arc_ok_volts(__comp_inst, t);
    } else if (arc_ok_in) {
        arc_ok_out = 1;
        lost_timer = arc_lost_delay;
    } else {
        lost_timer -= t;
        if (lost_timer <= 0) arc_ok_out = 0;
    }
}

/* Debounce the raw ohmic sense while ohmic-enable is TRUE. */
static void pm_ohmic_sense(struct __comp_state *__comp_inst)
{
    if (!ohmic_enable) {
        ohmic_sense_out = 0;
        ohmic_on_n = ohmic_off_n = 0;
        return;
    }
    if (ohmic_sense_in) {
        ohmic_off_n = 0;
        if (++ohmic_on_n > ohmic_sense_on_delay) ohmic_sense_out = 1;
    } else {
        ohmic_on_n = 0;
        if (++ohmic_off_n > ohmic_sense_off_delay) ohmic_sense_out = 0;
    }
}

/* Statistics back to 0 (once each time a program starts running). */
static void pm_reset_stats(struct __comp_state *__comp_inst)
{
    cut_length = cut_time = paused_time = probe_time = rapid_time = run_time = torch_time = 0;
    pierce_count = 0;
}

/* Program pulses to halui cleared as the program reaches each status; run time and statistics. */
static void pm_program_status(struct __comp_state *__comp_inst, double t)
{
    if (program_is_idle) {
        program_stop = 0;
        program_resume = 0;
        stats_done = 0;
    } else if (program_is_paused) {
        program_pause = 0;
        paused_time += t;
        run_time += t;
    } else if (program_is_running) {
        program_run = 0;
        program_resume = 0;
        job = 1;
        if (!stats_done) {
            pm_reset_stats(__comp_inst);
            stats_done = 1;
        }
        run_time += t;
        if (motion_type == 1) rapid_time += t;
    }
}

/* offset-set-probe / offset-set-scribe deploy the probe or scribe while idle, until both are released. */
static void pm_deploy(struct __comp_state *__comp_inst)
{
    if (homed && program_is_idle && state_out == PM_IDLE && (offset_set_probe || offset_set_scribe)) {
        if (offset_set_probe) ohmic_enable = 1;
        if (offset_set_scribe) scribe_arm = 1;
        deploy = 1;
    } else if (deploy && !offset_set_probe && !offset_set_scribe) {
        ohmic_enable = 0;
        scribe_arm = 0;
        deploy = 0;
    }
}
