// responder_sim.cc: the responder's simulated machine (homing, jogs, MDI, program lines) and the EMC_STAT it publishes.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "responder.hh"

namespace {

// Shortest time an MDI line takes, s.
const double MDI_MIN_S = 0.01;

// Remove ( ... ) and ; comments.
std::string strip_comments(const std::string &text)
{
    std::string out;
    int depth = 0;
    for (char c : text) {
        if (c == ';' && depth == 0) break;
        if (c == '(') depth++;
        else if (c == ')' && depth > 0) depth--;
        else if (depth == 0) out += c;
    }
    return out;
}

// Parse an MDI line into an activity: G4 P dwells, axis words move, M2/M30 fail (false).
bool parse_mdi(const Machine &m, const std::string &text, Activity &a)
{
    static const char axes[] = "XYZABCUVW";
    std::string line = strip_comments(text);
    a = Activity();
    a.text = text;
    memcpy(a.target, m.pos, sizeof a.target);
    double dwell = -1, dist = 0;
    bool g4 = false;
    for (size_t i = 0; i < line.size(); i++) {
        char letter = static_cast<char>(toupper(static_cast<unsigned char>(line[i])));
        if (!isalpha(static_cast<unsigned char>(letter))) continue;
        char *end = nullptr;
        double v = strtod(line.c_str() + i + 1, &end);
        if (end == line.c_str() + i + 1) continue;
        i = static_cast<size_t>(end - line.c_str()) - 1;
        const char *axis = strchr(axes, letter);
        if (letter == 'M' && (v == 2 || v == 30)) return false;
        if (letter == 'G' && v == 4) g4 = true;
        if (letter == 'P') dwell = v;
        if (axis && *axis) {
            int k = static_cast<int>(axis - axes);
            a.has_target = true;
            a.target[k] = v;
            dist += (v - m.pos[k]) * (v - m.pos[k]);
        }
    }
    double duration = g4 && dwell >= 0 ? dwell : std::sqrt(dist) / m.cfg.max_velocity;
    a.exec_state = g4 ? EMC_TASK_EXEC_WAITING_FOR_DELAY : EMC_TASK_EXEC_WAITING_FOR_MOTION;
    a.until = m.now + (duration > MDI_MIN_S ? duration : MDI_MIN_S);
    return true;
}

// Start the next queued MDI when the interpreter is free.
void start_mdi(Machine &m)
{
    if (m.interp != EMC_TASK_INTERP_IDLE || m.mdi_queue.empty()) return;
    std::string text = m.mdi_queue.front();
    m.mdi_queue.pop_front();
    Activity a;
    if (!parse_mdi(m, text, a)) {
        m.rejected = true; // M2/M30 in MDI: RCS_ERROR without a message
        return;
    }
    for (int k = 0; k < 9 && a.has_target; k++)
        if (!((m.cfg.axis_mask >> k) & 1)) a.target[k] = m.pos[k];
    m.activity = a;
    m.interp = EMC_TASK_INTERP_READING;
    emc_set_text(m.status.task.command, text.c_str());
}

// Finish the running MDI when its time is up.
void finish_mdi(Machine &m)
{
    if (m.activity.until == 0 || m.now < m.activity.until || m.paused) return;
    if (m.activity.has_target) memcpy(m.pos, m.activity.target, sizeof m.pos);
    m.activity = Activity();
    m.interp = EMC_TASK_INTERP_IDLE;
    emc_set_text(m.status.task.command, "");
}

// Advance a running program one line every two cycles.
void run_program(Machine &m)
{
    if (m.activity.until != 0 || m.program.empty() || m.paused) return;
    if (m.interp != EMC_TASK_INTERP_READING && m.interp != EMC_TASK_INTERP_WAITING) return;
    if (m.now < m.next_line_at) return;
    m.next_line_at = m.now + 2 * m.cfg.cycle_s;
    if (++m.program_line > m.program_lines) {
        m.interp = EMC_TASK_INTERP_IDLE;
        m.status.task.readLine = 0;
        return;
    }
    m.interp = m.program_line == m.program_lines ? EMC_TASK_INTERP_WAITING : EMC_TASK_INTERP_READING;
    m.status.task.readLine = m.program_line;
    m.status.task.currentLine = m.program_line;
    m.status.task.motionLine = m.program_line;
}

// Move jogging axes and joints.
void move_jogs(Machine &m, double dt)
{
    for (int k = 0; k < 9; k++) {
        if (!m.enabled) m.jog_vel[k] = 0;
        if (m.jog_vel[k] == 0) continue;
        m.pos[k] += m.jog_vel[k] * dt;
        if (m.jog_to_target[k] && (m.jog_vel[k] > 0) == (m.pos[k] >= m.jog_target[k])) {
            m.pos[k] = m.jog_target[k];
            m.jog_vel[k] = 0;
        }
    }
    for (int j = 0; j < m.cfg.joints; j++) {
        if (!m.enabled) m.joint_jog_vel[j] = 0;
        if (j < 9) m.pos[j] += m.joint_jog_vel[j] * dt;
    }
}

// Fill the task part of the status.
void fill_task(Machine &m, EMC_TASK_STAT &t)
{
    t.mode = responder_task_mode(m);
    t.state = responder_task_state(m);
    // A paused program shows the interpreter PAUSED, as task reports it.
    bool program_paused = m.paused && m.interp != EMC_TASK_INTERP_IDLE && t.mode == EMC_TASK_MODE_AUTO;
    t.interpState = program_paused ? EMC_TASK_INTERP_PAUSED : m.interp;
    t.execState = m.activity.until != 0 ? m.activity.exec_state : EMC_TASK_EXEC_DONE;
    t.delayLeft = m.activity.exec_state == EMC_TASK_EXEC_WAITING_FOR_DELAY && m.activity.until > m.now
                      ? m.activity.until - m.now : 0;
    t.queuedMDIcommands = static_cast<int32_t>(m.mdi_queue.size());
    t.task_paused = m.paused;
    t.taskbeat++;
    t.echo_serial_number = m.echo_serial;
    t.command_type = m.command_type;
}

// Fill the motion part of the status.
void fill_motion(Machine &m, EMC_MOTION_STAT &mo)
{
    EMC_TRAJ_STAT &tr = mo.traj;
    tr.linearUnits = m.cfg.linear_units;
    tr.angularUnits = m.cfg.angular_units;
    tr.cycleTime = m.cfg.servo_s;
    tr.joints = m.cfg.joints;
    tr.spindles = m.cfg.spindles;
    tr.axis_mask = m.cfg.axis_mask;
    tr.mode = m.traj_mode;
    tr.enabled = m.enabled;
    tr.paused = m.paused;
    tr.velocity = m.cfg.default_velocity;
    tr.acceleration = m.cfg.default_acceleration;
    tr.maxAcceleration = m.cfg.max_acceleration;
    tr.kinematics_type = EMC_KINEMATICS_IDENTITY;
    double *p[9] = {&tr.position.tran.x, &tr.position.tran.y, &tr.position.tran.z, &tr.position.a,
                    &tr.position.b, &tr.position.c, &tr.position.u, &tr.position.v, &tr.position.w};
    bool moving = m.activity.until != 0 && m.activity.has_target;
    for (int k = 0; k < 9; k++) {
        *p[k] = m.pos[k];
        moving = moving || m.jog_vel[k] != 0;
    }
    tr.actualPosition = tr.position;
    tr.inpos = !moving;
    tr.motion_type = moving ? EMC_MOTION_TYPE_TRAVERSE : 0;
    tr.current_vel = 0;
    for (int j = 0; j < EMCMOT_MAX_JOINTS; j++) {
        EMC_JOINT_STAT &js = mo.joint[j];
        js.output = js.input = j < 9 ? m.pos[j] : 0;
        js.homing = m.home_done_at[j] != 0;
        js.homed = m.homed[j];
        js.enabled = m.enabled && j < m.cfg.joints;
    }
    mo.heartbeat += static_cast<uint64_t>(m.cfg.cycle_s / m.cfg.servo_s + 0.5);
}

} // namespace

// Queue an operator error.
void responder_error(Machine &m, const std::string &text)
{
    emc_send_operator_message(*m.err, EMC_OPERATOR_ERROR_TYPE, text.c_str());
}

bool responder_all_homed(const Machine &m)
{
    for (int j = 0; j < m.cfg.joints; j++)
        if (!m.homed[j]) return false;
    return true;
}

// E-stop -> ESTOP, motion disabled -> ESTOP_RESET, else ON (OFF is never reported).
int responder_task_state(const Machine &m)
{
    if (m.estop) return EMC_TASK_STATE_ESTOP;
    return m.enabled ? EMC_TASK_STATE_ON : EMC_TASK_STATE_ESTOP_RESET;
}

// FREE/TELEOP -> MANUAL, COORD -> the requested MDI or AUTO.
int responder_task_mode(const Machine &m)
{
    if (m.traj_mode != EMC_TRAJ_MODE_COORD) return EMC_TASK_MODE_MANUAL;
    return m.requested_mode == EMC_TASK_MODE_MANUAL ? EMC_TASK_MODE_MDI : m.requested_mode;
}

void responder_abort(Machine &m)
{
    m.mdi_queue.clear();
    m.activity = Activity();
    m.interp = EMC_TASK_INTERP_IDLE;
    m.paused = false;
    emc_set_text(m.status.task.command, "");
    m.status.task.readLine = 0;
    m.status.task.motionLine = 0;
    for (int k = 0; k < 9; k++) m.jog_vel[k] = 0;
    for (int j = 0; j < EMCMOT_MAX_JOINTS; j++) m.joint_jog_vel[j] = 0;
}

// One cycle of simulated time.
void responder_advance(Machine &m, double dt)
{
    for (int j = 0; j < m.cfg.joints; j++) {
        if (m.home_done_at[j] != 0 && m.now >= m.home_done_at[j]) {
            m.home_done_at[j] = 0;
            m.homed[j] = true;
            if (j < 9) m.pos[j] = 0;
        }
    }
    move_jogs(m, dt);
    finish_mdi(m);
    start_mdi(m);
    run_program(m);
}

// Build the status and write it.
void responder_publish_status(Machine &m)
{
    EMC_STAT &s = m.status;
    fill_task(m, s.task);
    fill_motion(m, s.motion);
    s.io.aux.estop = m.estop;
    emc_set_text(s.task.ini_filename, m.cfg.ini_path.c_str());
    s.task.programUnits = m.cfg.linear_units > 0.5 ? 2 : 1;
    s.echo_serial_number = m.echo_serial;
    s.command_type = m.command_type;
    bool joint_jog = false;
    for (int j = 0; j < m.cfg.joints; j++) joint_jog = joint_jog || m.joint_jog_vel[j] != 0;
    bool busy = m.interp != EMC_TASK_INTERP_IDLE || !m.mdi_queue.empty() || joint_jog;
    s.status = m.rejected ? RCS_ERROR : busy ? RCS_EXEC : RCS_DONE;
    s.task.status = s.status;
    m.stat->write(s);
}
