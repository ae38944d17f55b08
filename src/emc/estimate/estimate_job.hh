// estimate_job.hh: one estimate: interpreter -> canon -> interp list -> EMCMOT commands -> simulated motion, in simulated time.
#ifndef ESTIMATE_JOB_HH
#define ESTIMATE_JOB_HH

#include <memory>
#include <string>

#include "estimate_report.hh"
#include "interp.hh"
#include "motion_translate.hh"
#include "sim_motion.hh"
#include "task_canon.hh"
#include "tool_table.hh"

// Runs a program the way milltask issues it: moves while the motion queue has room, everything
// else once motion is done (its precondition), dwells as idle cycles, tool changes in no time;
// the interpreter synchs with the simulated machine after probes, M66 and tool changes.  Probes
// trip at their end point; inputs read 0.
class EstimateJob : public CanonMachine {
public:
    EstimateJob(const MachineConfig &cfg, const kins_coords_t &coords, EstimateReport &report);
    ~EstimateJob() override;
    // Configure motion, the tool table and the interpreter (parameters from a copy of the var
    // file, which is never written); false with *error.
    bool setup(std::string *error);
    // Run program to its end; false with *error ("FILE:LINE: what").
    bool run(const std::string &program, std::string *error);
    // Where motion starts: the joints' HOME positions through the kinematics.
    EmcPose home_pose() const;

    // ---- CanonMachine ----
    EmcPose position() override { return sim_.position(); }
    EmcPose probed_position() override { return sim_.position(); }
    double probe_tripped_value() override { return 1.0; }
    int digital_input(int) override { return 0; }
    double analog_input(int) override { return 0.0; }
    int tool_slot() override { return 0; }
    int selected_tool_slot() override { return prepared_index_; }
    int tool_index(int toolno) override;
    bool queue_empty() override { return sim_.done(); }
    int toolchanger_fault() override { return 0; }
    int toolchanger_reason() override { return 0; }

private:
    bool issue_list(std::string *error);
    bool issue(const QueuedMsg &q, std::string *error);
    bool to_motion(const QueuedMsg &q, std::string *error);
    bool task_item(const NMLmsg &m);
    bool line_result(InterpStatus st, std::string *error);
    void synch(const CanonBlockNeeds &needs);
    void step();
    void drain();
    bool copy_var_file(std::string *error);
    std::string where(int line) const;

    MachineConfig cfg_;
    kins_coords_t coords_;
    EstimateReport &report_;
    SimMotion sim_;
    MotionTranslator xl_;
    ToolTable tools_;
    InterpList list_;
    std::unique_ptr<TaskCanon> canon_;
    std::unique_ptr<Interp> interp_;
    std::string program_;
    std::string var_copy_;
    int tool_ = 0, prepared_tool_ = 0, prepared_index_ = -1;
};

#endif
