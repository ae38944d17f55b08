/* home_seq.c: homing runs: Home-All by sequence number, single joints, synchronised groups in step. */
#include "rtapi.h"
#include "home_priv.h"

/* Non-zero when joint j is in use (below SET_NUM_JOINTS and active). */
int home_joint_in_use(int j)
{
    return j < home.num_joints && home.env.joints[j].active;
}

/* |HOME_SEQUENCE| of joint j. */
static int abs_seq(int j)
{
    int s = home.joint[j].params.home_sequence;
    return s < 0 ? -s : s;
}

/* Non-zero when joint j takes part in Home-All. */
static int in_home_all(int j)
{
    return home_joint_in_use(j) && abs_seq(j) <= HOME_SEQUENCE_NONE;
}

/* Non-zero when some Home-All joint has |sequence| n. */
static int any_with(int n)
{
    for (int j = 0; j < home.num_joints; j++)
        if (in_home_all(j) && abs_seq(j) == n)
            return 1;
    return 0;
}

/* Non-zero when a homed joint must not be homed again. */
static int keeps_home(int j)
{
    return home.joint[j].homed && (home.joint[j].params.home_flags & EMCMOT_HOME_NO_REHOME);
}

/* Begin joint j; negative sequences make it a member of a group that moves in step. */
static void begin(int j)
{
    int seq = home.joint[j].params.home_sequence;

    home.joint[j].sync_group = seq < 0 ? -seq : 0;
    home_joint_begin(j);
}

/* Start every Home-All joint with |sequence| n. */
static void start_number(int n)
{
    for (int j = 0; j < home.num_joints; j++)
        if (in_home_all(j) && abs_seq(j) == n && !keeps_home(j))
            begin(j);
}

/* Refuse a second run while one is going. */
static int busy(void)
{
    if (!home.run_active)
        return 0;
    home.env.report("Homing not possible until current homing process is finished.\n");
    return 1;
}

/* Home-All: sequence 0 (or 1 when 0 is empty), 1, 2 ... until the first missing number. */
int home_seq_start_all(void)
{
    int n;

    if (busy())
        return -1;
    n = any_with(0) ? 0 : 1;
    if (!any_with(n))
        return 0;
    home.run_active = 1;
    home.run_all = 1;
    home.run_sequence = n;
    start_number(n);
    return 0;
}

/* One joint, or its whole group when its sequence is negative. */
int home_seq_start_joint(int j)
{
    int seq;

    if (busy())
        return -1;
    if (!home_joint_in_use(j)) {
        home.env.report("Cannot home joint %d: it is not active", j);
        return -1;
    }
    if (keeps_home(j))
        return 0;
    seq = home.joint[j].params.home_sequence;
    home.run_active = 1;
    home.run_all = 0;
    if (seq < 0) {
        for (int m = 0; m < home.num_joints; m++)
            if (home_joint_in_use(m) && home.joint[m].params.home_sequence == seq &&
                !keeps_home(m))
                begin(m);
    } else {
        begin(j);
    }
    return 0;
}

/* Stop every homing joint at once; joints that were not homing keep their homed flag. */
void home_seq_abort(void)
{
    for (int j = 0; j < HOME_MAX_JOINTS; j++)
        home_joint_stop(j);
    home.run_active = 0;
}

/* A joint of a synchronised group may start a move only when no member is behind it. */
int home_seq_group_ready(int j, int state)
{
    int g = home.joint[j].sync_group;

    if (g == 0)
        return 1;
    for (int m = 0; m < home.num_joints; m++) {
        const home_jstate_t *s = &home.joint[m];
        if (m != j && s->homing && s->sync_group == g && s->state < state)
            return 0;
    }
    return 1;
}

/* Non-zero while a joint of the run still homes. */
static int any_homing(void)
{
    for (int j = 0; j < home.num_joints; j++)
        if (home.joint[j].homing)
            return 1;
    return 0;
}

/* One cycle of the run: every homing joint, then the next sequence number or the end. */
void home_seq_cycle(void)
{
    home.run_completed = 0;
    if (!home.run_active)
        return;
    for (int j = 0; j < home.num_joints && home.run_active; j++)
        home_joint_cycle(j);
    if (!home.run_active || any_homing())
        return;
    if (home.run_all && any_with(home.run_sequence + 1)) {
        home.run_sequence++;
        start_number(home.run_sequence);
        for (int j = 0; j < home.num_joints && home.run_active; j++)
            home_joint_cycle(j);
        return;
    }
    home.run_active = 0;
    home.run_completed = 1;
}
