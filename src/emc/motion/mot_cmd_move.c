/* mot_cmd_move.c: queueing lines, arcs, probe moves and rigid taps, with their limit checks (motion.md sec. 6). */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_cmd.h"

/* How each move kind is named in messages. */
typedef struct move_kind {
    const char *limit_word;     /* "Linear move on line ..." */
    const char *state_word;     /* "need to be enabled, in coord mode for ... move" */
} move_kind_t;

/* Words for a move command code. */
static const move_kind_t *kind_of(int code)
{
    static const move_kind_t line = { "Linear", "linear" }, circle = { "Circular", "circular" },
        probe = { "Probe", "probe" }, tap = { "Rigid tap", "rigid tap" };
    switch (code) {
    case EMCMOT_SET_CIRCLE: return &circle;
    case EMCMOT_PROBE: return &probe;
    case EMCMOT_RIGID_TAP: return &tap;
    default: return &line;
    }
}

/* Refuse a move and abort the queue: the program stops, the machine stays on. */
static int refuse_move(int result)
{
    mot->tp_ops->abort(mot->tp);
    *mot->pins->coord_error = 1;
    return result;
}

/* Non-zero when an enabled joint sits on an unmasked hard limit. */
static int on_hard_limit(void)
{
    for (int j = 0; j < mot->num_joints; j++) {
        const mot_joint_t *joint = &mot->joint[j];
        if (joint->active && (joint->pos_hard || joint->neg_hard) && !joint->override_mask)
            return 1;
    }
    return 0;
}

/* Axis limits of the end point; 0, or -1 after reporting the first violation. */
static int check_axis_limits(const emcmot_command_t *c, const move_kind_t *kind)
{
    static const char letters[] = "XYZABCUVW";

    for (int a = 0; a < MOT_NUM_AXES; a++) {
        double v = mot_pose_get(&c->pos, a);
        const mot_axis_t *axis = &mot->axis[a];
        if (v > axis->max_limit || v < axis->min_limit) {
            mot_report("%s move on line %d would exceed %c's %s limit", kind->limit_word, c->id,
                       letters[a], v > axis->max_limit ? "positive" : "negative");
            return -1;
        }
    }
    return 0;
}

/* Joint limits of the end point through inverse kinematics; 0 or -1 after reporting. */
static int check_joint_limits(const emcmot_command_t *c, const move_kind_t *kind)
{
    double joints[MOT_MAX_JOINTS] = { 0 };

    for (int j = 0; j < mot->num_joints; j++)
        joints[j] = mot->joint[j].pos_cmd;
    if (mot_inverse_kins(&c->pos, joints) != 0) {
        mot_report("%s move on line %d: kinematicsInverse failed for its end point",
                   kind->limit_word, c->id);
        return -1;
    }
    for (int j = 0; j < mot->num_kins_joints; j++) {
        const mot_joint_t *joint = &mot->joint[j];
        if (!joint->active)
            continue;
        if (joints[j] > joint->max_limit) {
            mot_report("%s move on line %d would exceed joint %d's positive limit max:[%f]",
                       kind->limit_word, c->id, j, joint->max_limit);
            return -1;
        }
        if (joints[j] < joint->min_limit) {
            mot_report("%s move on line %d would exceed joint %d's negative limit min:[%f]",
                       kind->limit_word, c->id, j, joint->min_limit);
            return -1;
        }
    }
    return 0;
}

/* State and limit checks every move gets; OK or the refusal result. */
static int check_move(const emcmot_command_t *c)
{
    const move_kind_t *kind = kind_of(c->command);

    if (!mot->enabled || !mot->coord)
        return mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                          "need to be enabled, in coord mode for %s move", kind->state_word);
    if (on_hard_limit())
        return refuse_move(mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                                      "can't do %s move with limits exceeded", kind->state_word));
    if (check_axis_limits(c, kind) < 0 || check_joint_limits(c, kind) < 0) {
        if (c->command == EMCMOT_SET_LINE)
            mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1, "invalid params in linear command");
        else
            mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 0, "%s move on line %d exceeds a limit",
                       kind->limit_word, c->id);
        return refuse_move(EMCMOT_COMMAND_INVALID_PARAMS);
    }
    return EMCMOT_COMMAND_OK;
}

/* The override enables queued with a move. */
static uint32_t current_enables(void)
{
    uint32_t e = 0;

    if (mot->fs_enabled)
        e |= TP_ENABLE_FS;
    if (mot->num_spindles > 0 && mot->spindle[0].override_enabled)
        e |= TP_ENABLE_SS;
    if (mot->fh_enabled)
        e |= TP_ENABLE_FH;
    if (mot->af_enabled)
        e |= TP_ENABLE_AF;
    return e;
}

/* The locking-indexer joint a rotary-index move turns, or -1. */
static int indexer_joint(const emcmot_command_t *c, const EmcPose *start)
{
    if (c->motion_type != TP_MOTION_INDEXROTARY)
        return -1;
    for (int a = 3; a < 6; a++) {
        int lj = mot->axis[a].locking_joint;
        if (lj >= 0 && mot_pose_get(&c->pos, a) != mot_pose_get(start, a))
            return lj;
    }
    return -1;
}

/* Remember a queued segment (for the interp.* arc pins). */
static void shadow_push(const emcmot_command_t *c, const EmcPose *start)
{
    int slot = (mot->shadow_head + mot->shadow_count) % MOT_TP_QUEUE_SIZE;
    mot_shadow_seg_t *s = &mot->shadow[slot];

    s->id = c->id;
    s->is_circle = c->command == EMCMOT_SET_CIRCLE;
    s->clockwise = c->normal.z < 0.0;
    s->center = c->center;
    s->radius = hypot(start->tran.x - c->center.x, start->tran.y - c->center.y);
    if (mot->shadow_count < MOT_TP_QUEUE_SIZE)
        mot->shadow_count++;
    else
        mot->shadow_head = (mot->shadow_head + 1) % MOT_TP_QUEUE_SIZE;
}

/* Build the planner segment of a move command. */
static void fill_segment(tp_segment_t *seg, const emcmot_command_t *c, const EmcPose *start)
{
    static const tp_segment_kind_t kinds[] = {
        [EMCMOT_SET_LINE] = TP_SEG_LINE, [EMCMOT_SET_CIRCLE] = TP_SEG_CIRCLE,
        [EMCMOT_PROBE] = TP_SEG_LINE, [EMCMOT_RIGID_TAP] = TP_SEG_RIGID_TAP,
    };
    int feed;

    memset(seg, 0, sizeof *seg);
    seg->kind = kinds[c->command];
    seg->motion_type = (tp_motion_type_t)c->motion_type;
    if (c->command == EMCMOT_PROBE && c->motion_type == 0)
        seg->motion_type = TP_MOTION_PROBING;
    if (c->command == EMCMOT_RIGID_TAP && c->motion_type == 0)
        seg->motion_type = TP_MOTION_FEED;
    seg->end = c->pos;
    seg->center = c->center;
    seg->normal = c->normal;
    seg->turn = c->turn;
    seg->vel = c->vel;
    seg->ini_maxvel = c->ini_maxvel;
    seg->acc = c->acc;
    seg->jerk = c->jerk;
    seg->enables = current_enables();
    feed = seg->motion_type != TP_MOTION_TRAVERSE;
    seg->atspeed = feed && mot->atspeed_next_feed;
    seg->indexer_jnum = indexer_joint(c, start);
    seg->tap_uu_per_rev = c->tap_pitch != 0.0 ? c->tap_pitch : mot->spindle_sync;
    seg->id = c->id;
    seg->tag = c->tag;
}

/* Add a checked move to the planner. */
static int queue_move(const emcmot_command_t *c)
{
    tp_segment_t seg;
    EmcPose start;
    tp_result_t r;

    if (mot->tp_ops->is_done(mot->tp)) {
        mot->tp_ops->get_pos(mot->tp, &mot->queued_end);
        /* An idle planner restarts from where it stands (tpmod of this tree does not start
         * a rigid tap queued behind finished moves otherwise). */
        if (c->command == EMCMOT_RIGID_TAP)
            mot->tp_ops->set_pos(mot->tp, &mot->queued_end);
    }
    start = mot->queued_end;
    fill_segment(&seg, c, &start);
    r = mot->tp_ops->add(mot->tp, &seg);
    if (r == TP_ZERO_LENGTH)
        return EMCMOT_COMMAND_OK;
    if (r != TP_OK)
        return refuse_move(mot_refuse(r == TP_INVALID_PARAMS ? EMCMOT_COMMAND_INVALID_PARAMS
                                      : EMCMOT_COMMAND_BAD_EXEC, 1,
                                      "can't add %s move at line %d (planner result %d)",
                                      kind_of(c->command)->state_word, c->id, (int)r));
    if (seg.atspeed)
        mot->atspeed_next_feed = 0;
    shadow_push(c, &start);
    mot->queued_end = c->pos;
    *mot->pins->coord_error = 0;
    return EMCMOT_COMMAND_OK;
}

/* SET_LINE. */
int mot_cmd_set_line(const emcmot_command_t *c)
{
    int rc = check_move(c);
    return rc != EMCMOT_COMMAND_OK ? rc : queue_move(c);
}

/* SET_CIRCLE. */
int mot_cmd_set_circle(const emcmot_command_t *c)
{
    int rc = check_move(c);
    return rc != EMCMOT_COMMAND_OK ? rc : queue_move(c);
}

/* PROBE: the probe must start in the other state than the one the move looks for. */
int mot_cmd_probe(const emcmot_command_t *c)
{
    int away = (c->probe_type & EMCMOT_PROBE_AWAY) != 0;
    int rc = check_move(c);

    if (rc != EMCMOT_COMMAND_OK)
        return rc;
    if (!away && mot->probe_val)
        return refuse_move(mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                                      "Probe is already tripped when starting G38.2 or G38.3 move"));
    if (away && !mot->probe_val)
        return refuse_move(mot_refuse(EMCMOT_COMMAND_INVALID_COMMAND, 1,
                                      "Probe is already clear when starting G38.4 or G38.5 move"));
    rc = queue_move(c);
    if (rc == EMCMOT_COMMAND_OK) {
        mot->probing = 1;
        mot->probe_type = c->probe_type;
        mot->probe_tripped = 0;
        mot->probe_id = c->id;
    }
    return rc;
}

/* RIGID_TAP: needs a spindle to follow. */
int mot_cmd_rigid_tap(const emcmot_command_t *c)
{
    int rc = check_move(c);

    if (rc != EMCMOT_COMMAND_OK)
        return rc;
    if (c->spindle < 0 || c->spindle >= mot->num_spindles)
        return refuse_move(mot_refuse(EMCMOT_COMMAND_INVALID_PARAMS, 1,
                                      "rigid tap on non-existent spindle %d", c->spindle));
    return queue_move(c);
}

/* CLEAR_PROBE_FLAGS. */
int mot_cmd_clear_probe_flags(const emcmot_command_t *c)
{
    (void)c;
    mot->probing = 0;
    mot->probe_tripped = 0;
    return EMCMOT_COMMAND_OK;
}
