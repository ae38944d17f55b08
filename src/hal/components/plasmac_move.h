/* plasmac_move.h: plasmac's external offset moves (counts toward a target at a speed) and the
 * speeds and heights they use (included by plasmac.comp). */

/* Feed rates as counts per period. */
static int pm_setup_speed(struct __comp_state *__comp_inst)
{
    return pm_speed(__comp_inst, setup_feed_rate);
}

static int pm_probe_speed(struct __comp_state *__comp_inst)
{
    return probe_feed_rate < setup_feed_rate ? pm_speed(__comp_inst, probe_feed_rate)
                                             : pm_setup_speed(__comp_inst);
}

static int pm_thc_speed(struct __comp_state *__comp_inst)
{
    double f = mode == 2 ? thc_feed_rate * pid_p_gain / 100.0 : thc_feed_rate;
    int v = pm_speed(__comp_inst, f);
    return v < 1 ? 1 : v;
}

static int pm_recovery_speed(struct __comp_state *__comp_inst)
{
    return pm_counts(cut_feed_rate * vs * 0.5);
}

/* mm as machine units. */
static double pm_mm(struct __comp_state *__comp_inst, double mm)
{
    return mm * pm_upm(__comp_inst);
}

/* The offset counts that put the torch at absolute machine Z z. */
static int pm_z_counts_at(struct __comp_state *__comp_inst, double z)
{
    return pm_to_counts(__comp_inst, z - (axis_z_position - z_offset_current));
}

/* TRUE when an offset is at its target in counts and the applied offset agrees (LinuxCNC's test). */
static int pm_at(struct __comp_state *__comp_inst, int counts, double current, int target)
{
    return counts == target && (int)(current * offset_res) == (int)(target * offset_scale * offset_res);
}

/* Move the Z offset toward target at v counts per period; TRUE once it is there. */
static int pm_z_move(struct __comp_state *__comp_inst, int target, int v)
{
    z_offset_enable = 1;
    z_offset_counts = pm_toward(z_offset_counts, target, v);
    return pm_at(__comp_inst, z_offset_counts, z_offset_current, target);
}

/* Move the X and Y offsets toward (xt, yt) at v counts per period along the direction; TRUE once there. */
static int pm_xy_move(struct __comp_state *__comp_inst, int xt, int yt, int v)
{
    double dx = (double)xt - x_offset_counts, dy = (double)yt - y_offset_counts, d = hypot(dx, dy);
    int vx = d > 0 ? pm_counts(v * fabs(dx) / d) : 0, vy = d > 0 ? pm_counts(v * fabs(dy) / d) : 0;
    xy_offset_enable = 1;
    if (dx != 0 && vx < 1) vx = 1;
    if (dy != 0 && vy < 1) vy = 1;
    x_offset_counts = pm_toward(x_offset_counts, xt, vx);
    y_offset_counts = pm_toward(y_offset_counts, yt, vy);
    return pm_at(__comp_inst, x_offset_counts, x_offset_current, xt)
           && pm_at(__comp_inst, y_offset_counts, y_offset_current, yt);
}

/* The XY offsets a recovered cut starts from (0 without a recovery). */
static int pm_home_x(struct __comp_state *__comp_inst)
{
    return recovering ? x_target : 0;
}

static int pm_home_y(struct __comp_state *__comp_inst)
{
    return recovering ? y_target : 0;
}

/* Room at the top: the Z maximum less max-offset mm, as counts. */
static int pm_top_counts(struct __comp_state *__comp_inst)
{
    return pm_z_counts_at(__comp_inst, axis_z_max_limit - pm_mm(__comp_inst, max_offset));
}

/* The bottom guard: 0.25 mm above the Z minimum, as counts. */
static int pm_bottom_counts(struct __comp_state *__comp_inst)
{
    return pm_z_counts_at(__comp_inst, axis_z_min_limit + pm_mm(__comp_inst, PM_MM_BOTTOM));
}

/* The height above the material (counts over the probed zero) as counts. */
static int pm_height(struct __comp_state *__comp_inst, double height)
{
    return pm_counts(zero) + pm_to_counts(__comp_inst, height);
}
