// task_canon_io.cc: TaskCanon spindle, coolant, tool, override, I/O, text and program-control calls.
#include "task_canon.hh"

#include <cmath>

namespace {
constexpr double MM_PER_INCH = 25.4;
}

void TaskCanon::set_spindle_mode(int spindle, double css_max)
{
    if (spindle < 0 || spindle >= EMCMOT_MAX_SPINDLES) return;
    flush();
    css_max_[spindle] = css_max;
    if (dir_[spindle] != 0) emit_spindle_speed(spindle);
}

void TaskCanon::set_spindle_speed(int spindle, double speed)
{
    if (spindle < 0 || spindle >= EMCMOT_MAX_SPINDLES) return;
    flush();
    speed_[spindle] = speed;
    if (dir_[spindle] != 0) emit_spindle_speed(spindle);
}

// CSS numerator: rpm = factor / radius (mu), from surface speed S in feet or metres per minute.
static double css_factor(double surface, CanonUnits units, double linear_units)
{
    double mm_per_min = units == CANON_UNITS_INCHES ? surface * 12.0 * MM_PER_INCH : surface * 1000.0;
    return mm_per_min * linear_units / (2 * M_PI);
}

void TaskCanon::emit_spindle_speed(int spindle)
{
    EMC_SPINDLE_SPEED m;
    m.spindle = spindle;
    if (css_max_[spindle] > 0) {
        m.speed = dir_[spindle] * css_max_[spindle];
        m.factor = css_factor(speed_[spindle], units_, cfg_.linear_units);
        m.xoffset = g5x_.tran.x + g92_.tran.x + tool_.tran.x;
    } else {
        m.speed = dir_[spindle] * speed_[spindle];
    }
    list_.append(m, 0);
}

// M3 (dir 1) / M4 (dir -1): the next feed waits for at-speed.
void TaskCanon::spindle_on(int spindle, int dir)
{
    if (spindle < 0 || spindle >= EMCMOT_MAX_SPINDLES) return;
    flush();
    dir_[spindle] = dir;
    EMC_SPINDLE_ON m;
    m.spindle = spindle;
    m.wait_for_spindle_at_speed = 1;
    if (css_max_[spindle] > 0) {
        m.speed = dir * css_max_[spindle];
        m.factor = css_factor(speed_[spindle], units_, cfg_.linear_units);
        m.xoffset = g5x_.tran.x + g92_.tran.x + tool_.tran.x;
    } else {
        m.speed = dir * speed_[spindle];
    }
    list_.append(m, 0);
}

void TaskCanon::stop_spindle_turning(int spindle)
{
    if (spindle < 0 || spindle >= EMCMOT_MAX_SPINDLES) return;
    flush();
    dir_[spindle] = 0;
    EMC_SPINDLE_OFF m;
    m.spindle = spindle;
    list_.append(m, 0);
}

void TaskCanon::orient_spindle(int spindle, double angle, int mode)
{
    flush();
    dir_[spindle < 0 || spindle >= EMCMOT_MAX_SPINDLES ? 0 : spindle] = 0;
    EMC_SPINDLE_ORIENT m;
    m.spindle = spindle;
    m.orientation = angle;
    m.mode = mode;
    list_.append(m, 0);
}

void TaskCanon::wait_spindle_orient_complete(int spindle, double timeout)
{
    flush();
    EMC_SPINDLE_WAIT_ORIENT_COMPLETE m;
    m.spindle = spindle;
    m.timeout = timeout;
    list_.append(m, 0);
}

void TaskCanon::mist_on() { flush(); list_.append(EMC_COOLANT_MIST_ON(), 0); }
void TaskCanon::mist_off() { flush(); list_.append(EMC_COOLANT_MIST_OFF(), 0); }
void TaskCanon::flood_on() { flush(); list_.append(EMC_COOLANT_FLOOD_ON(), 0); }
void TaskCanon::flood_off() { flush(); list_.append(EMC_COOLANT_FLOOD_OFF(), 0); }

// T word: prepare tool toolno (pocket = its tool-data index).
void TaskCanon::select_tool(int toolno)
{
    flush();
    EMC_TOOL_PREPARE m;
    m.tool = toolno;
    m.pocket = machine_.tool_index(toolno);
    list_.append(m, 0);
}

// M6: with [EMCIO]TOOL_CHANGE_POSITION a rapid there first (machine coordinates; the axes it
// leaves out stay), then the change.
void TaskCanon::change_tool()
{
    flush();
    if (cfg_.tool_change_axes > 0) {
        EmcPose p = end_;
        double *axis[9] = {&p.tran.x, &p.tran.y, &p.tran.z, &p.a, &p.b, &p.c, &p.u, &p.v, &p.w};
        for (int i = 0; i < cfg_.tool_change_axes && i < 9; i++) *axis[i] = cfg_.tool_change_position[i];
        queue_line(0, p, EMC_MOTION_TYPE_TOOLCHANGE, -1);
    }
    list_.append(EMC_TOOL_LOAD(), 0);
    needs_.tool_data = true;
}

// M61 Q: index is the tool-data index of the tool now in the spindle (0 = no tool).
void TaskCanon::change_tool_number(int index)
{
    flush();
    EMC_TOOL_SET_NUMBER m;
    m.tool = index;
    list_.append(m, 0);
    needs_.tool_data = true;
}

// G10 L0: read the tool table file again.
void TaskCanon::reload_tooldata()
{
    flush();
    list_.append(EMC_TOOL_LOAD_TOOL_TABLE(), 0);
    needs_.tool_data = true;
}

// G10 L1/L10/L11: tool-table values arrive in machine units already (canon.md sec. 1).
void TaskCanon::set_tool_table_entry(int index, const CanonTool &t)
{
    flush();
    EMC_TOOL_SET_OFFSET m;
    m.pocket = index;
    m.toolno = t.toolno;
    m.offset.tran.x = t.offset.x; m.offset.tran.y = t.offset.y; m.offset.tran.z = t.offset.z;
    m.offset.a = t.offset.a; m.offset.b = t.offset.b; m.offset.c = t.offset.c;
    m.offset.u = t.offset.u; m.offset.v = t.offset.v; m.offset.w = t.offset.w;
    m.diameter = t.diameter;
    m.frontangle = t.frontangle;
    m.backangle = t.backangle;
    m.orientation = t.orientation;
    list_.append(m, 0);
    needs_.tool_data = true;
}

// M48-M53 enables: feed override (FO), spindle override (SO), feed hold (FH).
void TaskCanon::override_enable(NMLTYPE type, int spindle, bool on)
{
    flush();
    if (type == EMC_TRAJ_SET_FO_ENABLE_TYPE) {
        EMC_TRAJ_SET_FO_ENABLE m;
        m.mode = on;
        list_.append(m, 0);
    } else if (type == EMC_TRAJ_SET_SO_ENABLE_TYPE) {
        EMC_TRAJ_SET_SO_ENABLE m;
        m.mode = on;
        m.spindle = spindle;
        list_.append(m, 0);
    } else {
        feed_hold_ = on;
        EMC_TRAJ_SET_FH_ENABLE m;
        m.mode = on;
        list_.append(m, 0);
    }
}

void TaskCanon::enable_adaptive_feed()
{
    flush();
    adaptive_ = true;
    EMC_MOTION_ADAPTIVE m;
    m.status = 1;
    list_.append(m, 0);
}

void TaskCanon::disable_adaptive_feed()
{
    flush();
    adaptive_ = false;
    EMC_MOTION_ADAPTIVE m;
    m.status = 0;
    list_.append(m, 0);
}

// M62/M63 (with the next move) and M64/M65 (now).
void TaskCanon::digital_out(int n, bool on, bool now)
{
    flush();
    EMC_MOTION_SET_DOUT m;
    m.index = (uint8_t)n;
    m.start = m.end = on;
    m.now = now;
    list_.append(m, 0);
}

// M67 (with the next move) and M68 (now).
void TaskCanon::analog_out(int n, double v, bool now)
{
    flush();
    EMC_MOTION_SET_AOUT m;
    m.index = (uint8_t)n;
    m.start = m.end = v;
    m.now = now;
    list_.append(m, 0);
}

// M66: queue the wait; the interpreter reads #5399 after task's synch.
int TaskCanon::wait_input(int index, int input_type, int wait_type, double timeout)
{
    flush();
    EMC_AUX_INPUT_WAIT m;
    m.index = index;
    m.input_type = input_type ? EMC_AUX_INPUT_DIGITAL : EMC_AUX_INPUT_ANALOG;
    m.wait_type = wait_type;
    m.timeout = timeout;
    list_.append(m, 0);
    needs_.wait_input = true;
    needs_.wait_index = index;
    needs_.wait_digital = input_type != 0;
    return 0;
}

// Locking indexers are unlocked and locked by motion around the move itself.
void TaskCanon::lock_rotary(int, int) { flush(); }
void TaskCanon::unlock_rotary(int, int) { flush(); }

// (MSG,...): shown to the operator when execution gets there.
void TaskCanon::message(const std::string &text)
{
    flush();
    EMC_OPERATOR_DISPLAY m;
    emc_set_text(m.display, text.c_str());
    list_.append(m, 0);
}

// (LOGOPEN,...)/(LOGAPPEND,...)/(LOG,...)/(LOGCLOSE): written while the program is read.
void TaskCanon::logopen(const std::string &name)
{
    if (log_) fclose(log_);
    log_ = fopen(name.c_str(), "w");
}

void TaskCanon::logappend(const std::string &name)
{
    if (log_) fclose(log_);
    log_ = fopen(name.c_str(), "a");
}

void TaskCanon::log(const std::string &text)
{
    if (!log_) return;
    fprintf(log_, "%s\n", text.c_str());
    fflush(log_);
}

void TaskCanon::logclose()
{
    if (log_) fclose(log_);
    log_ = nullptr;
}

void TaskCanon::program_stop() { flush(); list_.append(EMC_TASK_PLAN_PAUSE(), 0); }
void TaskCanon::optional_program_stop() { flush(); list_.append(EMC_TASK_PLAN_OPTIONAL_STOP(), 0); }
void TaskCanon::program_end() { flush(); list_.append(EMC_TASK_PLAN_END(), 0); }
