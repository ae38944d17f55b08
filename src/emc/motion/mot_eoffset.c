/* mot_eoffset.c: step 13: external offsets (axis.L.eoffset-*) planned within their velocity/acceleration share. */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"

/* Add the planned external offsets to a world pose (coord and teleop). */
void mot_eoffset_apply(EmcPose *pos)
{
    for (int a = 0; a < MOT_NUM_AXES; a++)
        mot_pose_set(pos, a, mot_pose_get(pos, a) + mot->axis[a].ext_offset_tp.curr_pos);
}

/* Request of one axis: counts x scale accumulated (cleared by eoffset-clear), kept inside the
 * axis limits; *limited is set while the limits cut it. */
static double axis_request(int a, int *limited)
{
    mot_axis_t *axis = &mot->axis[a];
    mot_axis_pins_t *p = &mot->pins->axis[a];
    int counts = *p->eoffset_counts;
    int delta = axis->eoffset_counts_valid ? counts - axis->eoffset_counts_old : 0;
    double base = mot_pose_get(&mot->carte_pos_cmd, a) - axis->ext_offset_tp.curr_pos;
    double request;

    axis->eoffset_counts_old = counts;
    axis->eoffset_counts_valid = 1;
    if (*p->eoffset_clear)
        axis->eoffset_raw = 0.0;
    else if (*p->eoffset_enable && delta != 0 && isfinite(*p->eoffset_scale))
        axis->eoffset_raw += delta * *p->eoffset_scale;
    request = fmin(fmax(axis->eoffset_raw, axis->min_limit - base), axis->max_limit - base);
    if (request != axis->eoffset_raw)
        *limited = 1;
    axis->eoffset_request = request;
    return request;
}

/* 13. Plan every axis' offset toward its request (only while enabled in coord/teleop). */
void mot_external_offsets(void)
{
    int limited = 0, active = 0;

    for (int a = 0; a < MOT_NUM_AXES; a++) {
        mot_axis_t *axis = &mot->axis[a];
        simple_tp_t *tp = &axis->ext_offset_tp;
        double request = axis_request(a, &limited);
        tp->pos_cmd = request;
        tp->max_vel = axis->ext_offset_vel;
        tp->max_acc = axis->ext_offset_acc;
        tp->enable = mot->enabled && (mot->coord || mot->teleop);
        if (tp->max_vel > 0.0 && tp->max_acc > 0.0)
            simple_tp_update(tp, mot->servo_period);
        active |= tp->curr_pos != 0.0 || request != 0.0;
    }
    mot->eoffset_limited = limited;
    mot->eoffset_active = active;
}
