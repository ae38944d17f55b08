/* mot_control.c: motion-controller, the servo-period loop in LinuxCNC's order (motion.md sec. 3). */
#include "rtapi.h"
#include "mot_priv.h"
#include "mot_control.h"
#include "mot_jog.h"

/* Nanoseconds since the previous cycle (motion.servo.last-period). */
static void measure_period(void)
{
    long long now = rtapi_get_time();

    if (mot->last_cycle_ns != 0) {
        long long d = now - mot->last_cycle_ns;
        *mot->pins->servo_last_period = d > 0 && d < 0xffffffffLL ? (uint32_t)d : 0;
    }
    mot->last_cycle_ns = now;
}

/* Free mode: run the homing state machines; a completed Home-All goes to teleop. */
static void do_homing(void)
{
    int all_done;

    if (mot->coord || mot->teleop)
        return;
    mot_homing_inputs_update();
    all_done = mot->home->do_homing();
    mot_homing_outputs_apply();
    if (all_done && mot->enabled)
        mot->want_teleop = 1;
}

/* Apply a deferred planner-type switch once the queue is idle. */
static void apply_pending_planner_type(void)
{
    if (mot->planner_type_pending < 0 || !mot->tp_ops->is_done(mot->tp))
        return;
    if (mot->tp_ops->set_planner_type(mot->tp, (tp_planner_type_t)mot->planner_type_pending) == TP_OK)
        mot->planner_type = mot->planner_type_pending;
    else
        mot_report("planner type %d refused by the planner", mot->planner_type_pending);
    mot->planner_type_pending = -1;
}

/* The servo function. */
void mot_controller(void *arg, long period_ns)
{
    (void)arg;
    (void)period_ns;
    measure_period();
    mot->home->read_inputs();                   /* 1. homing inputs */
    mot_kins_switch_input();                    /* 2. switchable kinematics */
    mot_process_inputs();                       /* 3. spindles, feed scale, joints, limits */
    mot_jog_stop_inputs();
    mot_forward_kins_feedback();                /* 4. feedback pose */
    mot_probe_input();                          /* 5. probe */
    mot_check_faults();                         /* 6. faults */
    mot_mode_transitions();                     /* 7. enable/disable, free/teleop/coord */
    if (!*mot->pins->jog_inhibit) {             /* 8. jog wheels */
        mot_jog_wheels_joints();
        mot_jog_wheels_axes();
    }
    do_homing();                                /* 9. homing */
    apply_pending_planner_type();               /* 10. deferred planner type */
    mot_external_offsets();                     /* 13. external offsets (planned first so */
    mot_get_pos_cmds();                         /* 11. the pose of this cycle includes them) */
    mot_check_soft_limits();
    mot_compensate();                           /* 12. backlash and screw comp */
    mot_output();                               /* 14. outputs */
    mot->home->write_outputs();                 /* 15. homing output pins */
    mot->heartbeat++;                           /* 16. status */
    mot_status_publish();
}
