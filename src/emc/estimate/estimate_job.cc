// estimate_job.cc: the estimator's task: interpreter set-up, reading the program, issuing the interp list to the simulated motion.
#include "estimate_job.hh"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "inifile.hh"

namespace {

// What must hold before an item is issued (milltask's precondition table).
enum class Pre { QUEUE_ROOM, NOTHING, MOTION_DONE };

Pre precondition_of(NMLTYPE t)
{
    switch (t) {
    case EMC_TRAJ_LINEAR_MOVE_TYPE: case EMC_TRAJ_CIRCULAR_MOVE_TYPE: case EMC_TRAJ_PROBE_TYPE:
    case EMC_TRAJ_RIGID_TAP_TYPE:
        return Pre::QUEUE_ROOM;
    case EMC_TRAJ_SET_TERM_COND_TYPE: case EMC_TRAJ_SET_SPINDLESYNC_TYPE: case EMC_MOTION_SET_DOUT_TYPE:
    case EMC_MOTION_SET_AOUT_TYPE: case EMC_TRAJ_SET_FO_ENABLE_TYPE: case EMC_TRAJ_SET_SO_ENABLE_TYPE:
    case EMC_TRAJ_SET_FH_ENABLE_TYPE: case EMC_MOTION_ADAPTIVE_TYPE:
        return Pre::NOTHING;
    default:
        return Pre::MOTION_DONE;
    }
}

// Folder of a path ("." when it has none).
std::string folder_of(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

EstimateJob::EstimateJob(const MachineConfig &cfg, const kins_coords_t &coords, EstimateReport &report)
    : cfg_(cfg), coords_(coords), report_(report), sim_(cfg, coords), xl_(cfg), tools_(cfg.random_toolchanger)
{
    canon_ = std::make_unique<TaskCanon>(machine_canon_config(cfg), *this, list_);
}

EstimateJob::~EstimateJob()
{
    interp_.reset();
    if (!var_copy_.empty()) {
        unlink(var_copy_.c_str());
        unlink((var_copy_ + ".bak").c_str());
        rmdir(folder_of(var_copy_).c_str());
    }
}

EmcPose EstimateJob::home_pose() const
{
    double joints[KINS_MAX_JOINTS] = {0};
    for (int j = 0; j < (int)cfg_.joint.size() && j < KINS_MAX_JOINTS; j++) joints[j] = cfg_.joint[j].home;
    EmcPose p = {};
    kins_identity_forward(&coords_, joints, &p);
    return p;
}

int EstimateJob::tool_index(int toolno)
{
    if (toolno == 0 && !tools_.random()) return 0;
    return tools_.find(toolno);
}

// The interpreter reads and writes the var file: give it a private copy.
bool EstimateJob::copy_var_file(std::string *error)
{
    IniFile ini(cfg_.ini_path);
    auto var = ini.Find("PARAMETER_FILE", "RS274NGC");
    std::string src = var ? *var : "";
    if (!src.empty() && src[0] != '/') src = folder_of(cfg_.ini_path) + "/" + src;
    const char *tmp = getenv("TMPDIR");
    std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/openemc-estimate-XXXXXX";
    std::vector<char> buf(dir.begin(), dir.end());
    buf.push_back('\0');
    if (!mkdtemp(buf.data())) {
        *error = dir + ": " + strerror(errno);
        return false;
    }
    var_copy_ = std::string(buf.data()) + "/params.var";
    std::ifstream in(src);
    std::ofstream out(var_copy_);
    if (in) out << in.rdbuf();
    return true;
}

bool EstimateJob::setup(std::string *error)
{
    MotionCommands start;
    xl_.startup(start);
    for (const emcmot_command_t &c : start)
        if (!sim_.apply(c, error)) return false;
    IniFile ini(cfg_.ini_path);
    double servo_ns = 1e6, traj_ns = 0;
    if (auto v = ini.Find("SERVO_PERIOD", "EMCMOT")) servo_ns = atof(v->c_str());
    if (auto v = ini.Find("TRAJ_PERIOD", "EMCMOT")) traj_ns = atof(v->c_str());
    if (!(servo_ns > 0)) {
        *error = cfg_.ini_path + ": [EMCMOT]SERVO_PERIOD must be a positive number of nanoseconds";
        return false;
    }
    sim_.set_periods(servo_ns * 1e-9, traj_ns * 1e-9);
    report_.set_period(sim_.period(), sim_.servo_per_traj());
    sim_.set_position(home_pose());
    report_.start_at(sim_.position());
    std::vector<std::string> errors;
    if (!cfg_.tool_table.empty()) tools_.load(cfg_.tool_table, &errors);
    for (const std::string &e : errors) fprintf(stderr, "openemc-estimate: %s\n", e.c_str());
    if (!copy_var_file(error)) return false;
    interp_ = std::make_unique<Interp>(*canon_);
    if (!interp_->load_ini(cfg_.ini_path)) {
        *error = cfg_.ini_path + ": interpreter can't read the INI file";
        return false;
    }
    interp_->set_var_file(var_copy_);
    interp_->set_task(true);
    interp_->set_start_in_machine_units(true);
    interp_->set_tools(tools_.canon_tools());
    canon_->set_position(sim_.position());
    xl_.set_position(sim_.position());
    try {
        interp_->init();
    } catch (const std::exception &e) {
        *error = std::string("interpreter init failed: ") + e.what();
        return false;
    }
    list_.clear();
    return true;
}

// "program:line: " for messages about a source line.
std::string EstimateJob::where(int line) const { return program_ + ":" + std::to_string(line) + ": "; }

// One trajectory cycle, counted with the tool in the spindle.
void EstimateJob::step() { report_.add(sim_.cycle(), tool_); }

// Run cycles until the queue is empty and motion at rest.
void EstimateJob::drain()
{
    while (!sim_.done()) step();
}

bool EstimateJob::to_motion(const QueuedMsg &q, std::string *error)
{
    MotionCommands cmds;
    std::string why;
    if (!xl_.translate(*q.msg(), cmds, &why)) return true;
    if (!why.empty()) {
        *error = where(q.line) + why;
        return false;
    }
    for (const emcmot_command_t &c : cmds) {
        if (!sim_.apply(c, &why)) {
            *error = where(q.line) + why;
            return false;
        }
    }
    return true;
}

// Items task handles itself; true when m was one of them.
bool EstimateJob::task_item(const NMLmsg &m)
{
    switch (m.type) {
    case EMC_TRAJ_DELAY_TYPE: {
        long n = std::lround(emc_msg_as<EMC_TRAJ_DELAY>(&m)->delay / sim_.period());
        for (long k = 0; k < n; k++) step();
        return true;
    }
    case EMC_TOOL_PREPARE_TYPE:
        prepared_tool_ = emc_msg_as<EMC_TOOL_PREPARE>(&m)->tool;
        prepared_index_ = tools_.find(prepared_tool_);
        return true;
    case EMC_TOOL_LOAD_TYPE:
        tool_ = prepared_tool_;
        prepared_index_ = -1;
        return true;
    case EMC_TOOL_SET_NUMBER_TYPE:
        tool_ = emc_msg_as<EMC_TOOL_SET_NUMBER>(&m)->tool;
        return true;
    default:
        return false;
    }
}

bool EstimateJob::issue(const QueuedMsg &q, std::string *error)
{
    const NMLmsg &m = *q.msg();
    switch (precondition_of(m.type)) {
    case Pre::QUEUE_ROOM:
        while (sim_.queue_full()) step();
        break;
    case Pre::MOTION_DONE:
        drain();
        // non-moves carry no line: the list is issued after every line read, so it is that one
        report_.set_line(q.line > 0 ? q.line : interp_->state().sequence_number);
        if (task_item(m)) return true;
        break;
    case Pre::NOTHING:
        break;
    }
    return to_motion(q, error);
}

bool EstimateJob::issue_list(std::string *error)
{
    while (!list_.empty())
        if (!issue(list_.pop(), error)) return false;
    return true;
}

// The interpreter catches up with the machine: position, probe result, input, tools.
void EstimateJob::synch(const CanonBlockNeeds &needs)
{
    EmcPose pos = sim_.position();
    canon_->set_position(pos);
    xl_.set_position(pos);
    InterpState &s = interp_->state();
    CanonPose p = canon_->to_program(pos);
    s.current = Pose{p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
    if (needs.probe) {
        const double v[9] = {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
        for (int i = 0; i < 9; i++) s.params[5061 + i] = v[i];
        s.params[5070] = 1.0;
    }
    if (needs.wait_input) s.params[5399] = 0.0;
    interp_->set_tools(tools_.canon_tools());
    int idx = tools_.find(tool_);
    s.current_pocket = tools_.random() ? 0 : (idx > 0 ? idx : 0);
    s.selected_pocket = prepared_index_;
}

// Handle one interpreter result; false when the program ended (error set on failure).
bool EstimateJob::line_result(InterpStatus st, std::string *error)
{
    CanonBlockNeeds needs = canon_->take_needs();
    if (st == INTERP_ERROR) {
        *error = where(interp_->state().sequence_number) + interp_->error_text();
        return false;
    }
    if (st == INTERP_EXIT || st == INTERP_ENDFILE) canon_->flush();
    if (!issue_list(error)) return false;
    if (st == INTERP_EXIT || st == INTERP_ENDFILE) return false;
    if (st == INTERP_EXECUTE_FINISH || needs.probe || needs.wait_input || needs.tool_data) {
        canon_->flush();
        if (!issue_list(error)) return false;
        drain();
        synch(needs);
    }
    return true;
}

bool EstimateJob::run(const std::string &program, std::string *error)
{
    program_ = program;
    if (access(program.c_str(), R_OK) != 0) {
        *error = program + ": " + strerror(errno);
        return false;
    }
    try {
        interp_->open(program);
    } catch (const std::exception &e) {
        *error = program + ": " + e.what();
        return false;
    }
    error->clear();
    while (line_result(interp_->execute_next(), error)) {
    }
    if (!error->empty()) return false;
    report_.set_last_line(interp_->state().sequence_number);
    drain();
    return true;
}
