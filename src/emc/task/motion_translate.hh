// motion_translate.hh: NML messages -> EMCMOT commands, and the configuration stream task sends motion at start-up.
#ifndef MOTION_TRANSLATE_HH
#define MOTION_TRANSLATE_HH

#include <string>
#include <vector>

#include "emc_nml.hh"
#include "machine_config.hh"
#include "motion_cmd.h"

using MotionCommands = std::vector<emcmot_command_t>;

// Pure translation (no HAL, no shared memory): milltask pushes the result into motion's
// command ring, openemc-estimate into its simulated motion.  The translator remembers what
// a stream needs across messages: joint limits (min and max travel in one command), and
// where the last queued move ended (a move's jerk limit depends on its direction).
class MotionTranslator {
public:
    explicit MotionTranslator(const MachineConfig &cfg);

    // The configuration stream of LinuxCNC's task start-up (motion.md sec. 2 "Startup stream").
    void startup(MotionCommands &out);
    // Commands for msg; false when msg is not for motion (task, io or an unknown type).
    // *error explains a message that is for motion but unusable (e.g. a comp file that fails).
    bool translate(const NMLmsg &msg, MotionCommands &out, std::string *error = nullptr);
    // Motion abort: every joint's jog, then the planner (JOG_ABORT x16, ABORT).
    void motion_abort(MotionCommands &out) const;
    // SPINDLE_OFF for every configured spindle.
    void spindles_off(MotionCommands &out) const;
    // Where the next move starts (machine coordinates).
    void set_position(const EmcPose &p) { last_end_ = p; }
    const MachineConfig &config() const { return cfg_; }

    // One command of the given code with LinuxCNC's "none" defaults.
    static emcmot_command_t make(emcmot_command_code_t code);

private:
    void startup_traj(MotionCommands &out) const;
    void startup_joint(int j, MotionCommands &out);
    void startup_axis(int a, MotionCommands &out) const;
    double move_jerk(const EmcPose &end) const;

    MachineConfig cfg_;
    std::vector<double> min_limit_, max_limit_;
    EmcPose last_end_ = {};

public:
    // Handlers of the translation table (one per message type).
    struct Ctx {
        MotionTranslator &self;
        const NMLmsg &msg;
        MotionCommands &out;
        std::string *error;
    };
    struct Entry {
        NMLTYPE type;
        bool (*fn)(Ctx &);
    };
    static const Entry *table(size_t *count);
    // joint limit bookkeeping for the handlers
    void set_joint_limits(int joint, double min, double max, MotionCommands &out);
    double joint_min(int j) const { return j >= 0 && j < (int)min_limit_.size() ? min_limit_[j] : 0; }
    double joint_max(int j) const { return j >= 0 && j < (int)max_limit_.size() ? max_limit_[j] : 0; }
    double jerk_to(const EmcPose &end) { double j = move_jerk(end); last_end_ = end; return j; }
};

// JOINT_HOMING_PARAMS flags of a joint (EMCMOT_HOME_*).
int motion_home_flags(const JointConfig &j);

#endif
