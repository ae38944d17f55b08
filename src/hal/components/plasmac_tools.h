/* plasmac_tools.h: plasmac scribe, spotting, ohmic probe retries and offset probing (included by plasmac.comp). */

/* End scribing: scribe off, then idle, or pause when the program paused. */
static void plasmac_scribe_end(struct __comp_state *__comp_inst)
{
    scribe_arm = 0;
    scribe_on = 0;
    if (program_is_paused)
        plasmac_abort(__comp_inst, PM_ERR_NONE, PM_STOP_PAUSE);
    else
        plasmac_goto(__comp_inst, PM_IDLE);
}

/* TRUE when scribing must end: request gone or program paused. */
static int plasmac_scribe_ending(struct __comp_state *__comp_inst)
{
    return !plasmac_request(__comp_inst) || program_is_paused;
}

/* SCRIBE_ARM: scribe armed, switched on after scribe-arm-delay. */
static void plasmac_scribe_arm_state(struct __comp_state *__comp_inst, double dt)
{
    timer += dt;
    scribe_arm = 1;
    if (plasmac_scribe_ending(__comp_inst)) {
        plasmac_scribe_end(__comp_inst);
    } else if (timer >= scribe_arm_delay) {
        scribe_on = 1;
        plasmac_goto(__comp_inst, PM_SCRIBE_ON);
    }
}

/* SCRIBE_ON: scribe on, motion released after scribe-on-delay. */
static void plasmac_scribe_on_state(struct __comp_state *__comp_inst, double dt)
{
    timer += dt;
    if (plasmac_scribe_ending(__comp_inst))
        plasmac_scribe_end(__comp_inst);
    else if (timer >= scribe_on_delay)
        plasmac_goto(__comp_inst, PM_SCRIBING);
}

/* SCRIBING: motion runs with the scribe on until the request ends. */
static void plasmac_scribing(struct __comp_state *__comp_inst, double dt)
{
    (void)dt;
    if (plasmac_scribe_ending(__comp_inst))
        plasmac_scribe_end(__comp_inst);
}

/* SPOTTING: torch on; spotting-time ms after the voltage reaches the threshold, torch off. */
static void plasmac_spotting(struct __comp_state *__comp_inst, double dt)
{
    if (!torch_on) {
        torch_on = 1;
        spot_armed = 0;
        return;
    }
    if (!spot_armed && volts >= spotting_threshold) {
        spot_armed = 1;
        timer = 0.0;
    }
    if (!spot_armed)
        return;
    timer += dt;
    if (timer * 1000.0 >= spotting_time) {
        plasmac_leave_cut(__comp_inst);
        plasmac_goto(__comp_inst, PM_END_CUT);
    }
}

/* OHMIC_RETRY: float switch tripped without ohmic contact: rise until it opens, probe again. */
static void plasmac_ohmic_retry(struct __comp_state *__comp_inst, double dt)
{
    if (!float_switch)
        plasmac_goto(__comp_inst, PM_PROBE_DOWN);
    else if (plasmac_move_z(__comp_inst, axis_z_max_limit, probe_feed_rate, dt))
        plasmac_probe_failed(__comp_inst);
}

/* OFFSET_PROBE: move X/Y by the probe offset, wait offset-probe-delay, then probe. */
static void plasmac_offset_probe(struct __comp_state *__comp_inst, double dt)
{
    if (!plasmac_move_xy(__comp_inst, probe_x0 + offset_probe_x, probe_y0 + offset_probe_y,
                         xy_feed_rate, dt))
        return;
    timer += dt;
    if (timer >= offset_probe_delay)
        plasmac_goto(__comp_inst, PM_PROBE_HEIGHT);
}

/* OFFSET_RETURN: move X/Y back from the probe offset, then go on as after any probe. */
static void plasmac_offset_return(struct __comp_state *__comp_inst, double dt)
{
    if (!plasmac_move_xy(__comp_inst, probe_x0, probe_y0, xy_feed_rate, dt))
        return;
    probe_offset_used = 0;
    plasmac_goto(__comp_inst, probe_testing ? PM_PROBE_TEST : PM_PIERCE_HEIGHT);
}
