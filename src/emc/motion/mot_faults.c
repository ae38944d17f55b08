/* mot_faults.c: steps 5 and 6: the probe input and the faults that switch motion off (motion.md sec. 6). */
#include "rtapi.h"
#include "rtapi_math.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_jog.h"

/* Disable motion now: the amplifiers drop in this same cycle (step 7 runs next). */
static void fault(int code)
{
    mot->enabling = 0;
    if (mot->fault_code == EMCMOT_FAULT_NONE)
        mot->fault_code = code;
}

/* A probe move saw the state it looked for: latch the position and stop. */
static void probe_trip(void)
{
    mot->probed_pos = mot->carte_pos_fb_ok ? mot->carte_pos_fb : mot->carte_pos_cmd;
    mot->probe_tripped = 1;
    mot->probing = 0;
    mot->tp_ops->abort(mot->tp);
}

/* A probe move ended without the wanted state. */
static void probe_missed(void)
{
    mot->probing = 0;
    if (mot->probe_type & EMCMOT_PROBE_NO_ERROR)
        return;
    if (mot->probe_type & EMCMOT_PROBE_AWAY)
        mot_report("G38.4 move finished without breaking contact.");
    else
        mot_report("G38.2 move finished without making contact.");
    mot->tp_ops->abort(mot->tp);
}

/* The probe went active while something other than a probe move ran. */
static void probe_unexpected(void)
{
    if (mot->coord && !mot->tp_ops->is_done(mot->tp)) {
        mot_report("Probe tripped during non-probe move.");
        mot->tp_ops->abort(mot->tp);
    } else if (mot->teleop && mot_jog_active()) {
        mot_report("Probe tripped during a coordinate jog.");
        mot_abort_jogs();
    } else if (!mot->coord && !mot->teleop && mot->home->homing_active()) {
        if (mot->probe_err_inhibit_home)
            return;
        mot_report("Probe tripped during homing motion.");
        mot->home->cancel();
    } else if (!mot->coord && !mot->teleop && mot_jog_active()) {
        if (mot->probe_err_inhibit_jog)
            return;
        mot_report("Probe tripped during a joint jog.");
        mot_abort_jogs();
    }
}

/* 5. Probe input: trips probe moves, guards everything else on the rising edge. */
void mot_probe_input(void)
{
    int val = *mot->pins->probe_input != 0;
    int rising = val && !mot->probe_val;

    mot->probe_val = val;
    if (!mot->enabled)
        return;
    if (mot->probing && mot->coord) {
        int want = (mot->probe_type & EMCMOT_PROBE_AWAY) ? !val : val;
        if (want && mot->motion_type == TP_MOTION_PROBING)
            probe_trip();
        else if (mot->tp_ops->is_done(mot->tp))
            probe_missed();
        return;
    }
    if (rising)
        probe_unexpected();
}

/* Hard limit, amplifier fault and following error of one joint. */
static void joint_faults(int j)
{
    mot_joint_t *joint = &mot->joint[j];

    if (!joint->active)
        return;
    if ((joint->pos_hard || joint->neg_hard) && !joint->override_mask &&
        !mot->home->joint_homing(j)) {
        joint->error = 1;
        mot_report("joint %d on limit switch error", j);
        fault(EMCMOT_FAULT_HARD_LIMIT);
    }
    if (joint->amp_fault) {
        joint->error = 1;
        joint->faulted = 1;
        mot_report("joint %d amplifier fault", j);
        fault(EMCMOT_FAULT_AMP);
    }
    if (fabs(joint->ferror) > joint->ferror_limit) {
        joint->error = 1;
        joint->ferror_tripped = 1;
        mot_report("joint %d following error", j);
        fault(EMCMOT_FAULT_FERROR);
    }
}

/* 6. Faults: any of them disables motion (machine off, not E-stop). */
void mot_check_faults(void)
{
    if (!mot->enabled)
        return;
    if (!*mot->pins->enable) {
        mot_report("motion stopped by enable input");
        fault(EMCMOT_FAULT_ENABLE_INPUT);
    }
    for (int j = 0; j < mot->num_joints; j++)
        joint_faults(j);
    for (int s = 0; s < mot->num_spindles; s++) {
        if (*mot->pins->spindle[s].amp_fault_in) {
            mot_report("spindle %d amplifier fault", s);
            fault(EMCMOT_FAULT_SPINDLE_AMP);
        }
    }
    for (int i = 0; i < mot->num_misc_error; i++) {
        if (*mot->pins->misc_error[i]) {
            mot_report("Motion Stopped by misc error %d", i);
            fault(EMCMOT_FAULT_MISC_ERROR);
        }
    }
}
