/* plasmac_recovery.h: plasmac cut recovery and laser recovery moves while paused (included by plasmac.comp). */

/* RECOVER_RETURN: cutting from a recovery offset, move X/Y back onto the path at cut feed. */
static void plasmac_recover_return(struct __comp_state *__comp_inst, double dt)
{
    plasmac_cut_stats(__comp_inst, dt);
    if (plasmac_move_xy(__comp_inst, 0.0, 0.0, cut_feed_rate, dt))
        plasmac_goto(__comp_inst, mode == 2 ? PM_CUT_MODE_2 : PM_CUT_MODE_01);
}

/* CUT_RECOVERY: while cut-recovery is TRUE, X/Y follow x-offset, y-offset; they stay on release. */
static void plasmac_cut_recovery(struct __comp_state *__comp_inst, double dt)
{
    if (!cut_recovery || !program_is_paused)
        plasmac_goto(__comp_inst, PM_PAUSED);
    else
        plasmac_move_xy(__comp_inst, x_offset, y_offset, xy_feed_rate, dt);
}

/* LASER_RECOVERY: X/Y to the laser offsets while requested, then back; reports its phase. */
static void plasmac_laser_recovery(struct __comp_state *__comp_inst, double dt)
{
    int go = laser_recovery_start && program_is_paused;
    double tx = go ? laser_x_offset : 0.0, ty = go ? laser_y_offset : 0.0;
    int there = plasmac_move_xy(__comp_inst, tx, ty, xy_feed_rate, dt);
    if (go) {
        laser_recovery_state = there ? PM_LASER_THERE : PM_LASER_MOVING;
    } else if (!there) {
        laser_recovery_state = PM_LASER_BACK;
    } else {
        laser_recovery_state = PM_LASER_NONE;
        plasmac_goto(__comp_inst, PM_PAUSED);
    }
}
