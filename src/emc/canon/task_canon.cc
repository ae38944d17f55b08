// task_canon.cc: TaskCanon set-up calls (units, offsets, feeds, path control) and the queries the interpreter makes.
#include "task_canon.hh"

#include <cmath>

TaskCanon::TaskCanon(const CanonConfig &cfg, CanonMachine &machine, InterpList &list)
    : cfg_(cfg), machine_(machine), list_(list)
{
}

TaskCanon::~TaskCanon()
{
    if (log_) fclose(log_);
}

// Reset the canon to its power-on state (offsets none, mm, continuous path, no held chain).
void TaskCanon::init_canon()
{
    chain_.clear();
    g5x_ = g92_ = tool_ = EmcPose{};
    g5x_index_ = 1;
    rotation_ = 0;
    units_ = CANON_UNITS_MM;
    plane_ = CANON_PLANE_XY;
    feed_ = 0;
    feed_mode_ = 0;
    motion_mode_ = CANON_CONTINUOUS;
    tolerance_ = naivecam_tol_ = 0;
    end_ = machine_.position();
}

// Millimetres per program length unit.
double TaskCanon::mm_per_unit() const
{
    switch (units_) {
    case CANON_UNITS_INCHES: return 25.4;
    case CANON_UNITS_CM: return 10.0;
    default: return 1.0;
    }
}

// Machine units per program unit; exactly 1 when program and machine units agree.
double TaskCanon::unit_factor() const
{
    double f = mm_per_unit() * cfg_.linear_units;
    return std::fabs(f - 1.0) < 1e-9 ? 1.0 : f;
}

// A program pose converted to machine units, no offsets applied.
static EmcPose scaled(const CanonPose &p, double lin, double ang)
{
    EmcPose e;
    e.tran.x = p.x * lin; e.tran.y = p.y * lin; e.tran.z = p.z * lin;
    e.a = p.a * ang; e.b = p.b * ang; e.c = p.c * ang;
    e.u = p.u * lin; e.v = p.v * lin; e.w = p.w * lin;
    return e;
}

// Offsets given in program units, as machine units.
EmcPose TaskCanon::offsets_pose(const CanonPose &p) const
{
    return scaled(p, unit_factor(), cfg_.angular_units);
}

// machine = Rot_Z(rotation)·(p + g92) + g5x + tool offset (canon.md sec. 1).
EmcPose TaskCanon::to_machine(const CanonPose &p) const
{
    EmcPose e = offsets_pose(p);
    double x = e.tran.x + g92_.tran.x, y = e.tran.y + g92_.tran.y;
    double r = rotation_ * M_PI / 180.0;
    e.tran.x = x * cos(r) - y * sin(r) + g5x_.tran.x + tool_.tran.x;
    e.tran.y = x * sin(r) + y * cos(r) + g5x_.tran.y + tool_.tran.y;
    e.tran.z += g92_.tran.z + g5x_.tran.z + tool_.tran.z;
    e.a += g92_.a + g5x_.a + tool_.a;
    e.b += g92_.b + g5x_.b + tool_.b;
    e.c += g92_.c + g5x_.c + tool_.c;
    e.u += g92_.u + g5x_.u + tool_.u;
    e.v += g92_.v + g5x_.v + tool_.v;
    e.w += g92_.w + g5x_.w + tool_.w;
    return e;
}

// The inverse of to_machine.
CanonPose TaskCanon::to_program(const EmcPose &m) const
{
    double lin = unit_factor(), ang = cfg_.angular_units;
    double x = m.tran.x - g5x_.tran.x - tool_.tran.x, y = m.tran.y - g5x_.tran.y - tool_.tran.y;
    double r = -rotation_ * M_PI / 180.0;
    CanonPose p;
    p.x = (x * cos(r) - y * sin(r) - g92_.tran.x) / lin;
    p.y = (x * sin(r) + y * cos(r) - g92_.tran.y) / lin;
    p.z = (m.tran.z - g5x_.tran.z - tool_.tran.z - g92_.tran.z) / lin;
    p.a = (m.a - g5x_.a - tool_.a - g92_.a) / ang;
    p.b = (m.b - g5x_.b - tool_.b - g92_.b) / ang;
    p.c = (m.c - g5x_.c - tool_.c - g92_.c) / ang;
    p.u = (m.u - g5x_.u - tool_.u - g92_.u) / lin;
    p.v = (m.v - g5x_.v - tool_.v - g92_.v) / lin;
    p.w = (m.w - g5x_.w - tool_.w - g92_.w) / lin;
    return p;
}

void TaskCanon::set_g5x_offset(int origin, const CanonPose &p)
{
    flush();
    g5x_ = offsets_pose(p);
    g5x_index_ = origin;
    EMC_TRAJ_SET_G5X m;
    m.g5x_index = origin;
    m.origin = g5x_;
    list_.append(m, 0);
}

void TaskCanon::set_g92_offset(const CanonPose &p)
{
    flush();
    g92_ = offsets_pose(p);
    EMC_TRAJ_SET_G92 m;
    m.origin = g92_;
    list_.append(m, 0);
}

void TaskCanon::set_xy_rotation(double deg)
{
    flush();
    rotation_ = deg;
    EMC_TRAJ_SET_ROTATION m;
    m.rotation = deg;
    list_.append(m, 0);
}

// Units change the meaning of later numbers only: stored values are machine units already.
void TaskCanon::use_length_units(CanonUnits u)
{
    units_ = u;
}

// G93/G94 (0) or G95 (1); leaving G95 or any G94 stops velocity-mode spindle sync.
void TaskCanon::set_feed_mode(int spindle, int mode)
{
    flush();
    feed_mode_ = mode;
    feed_spindle_ = spindle;
    if (mode == 0)
        emit_sync(spindle, 0, false);
    else
        emit_sync(spindle, feed_, true);
}

// F in program units per minute (G94/G93) or per revolution (G95).
void TaskCanon::set_feed_rate(double rate)
{
    flush();
    if (feed_mode_ == 1) {
        feed_ = to_mu(rate);
        emit_sync(feed_spindle_, feed_, true);
    } else {
        feed_ = to_mu(rate) / 60.0;
    }
    feed_prog_ = rate;
}

void TaskCanon::emit_sync(int spindle, double fpr_mu, bool velocity_mode)
{
    EMC_TRAJ_SET_SPINDLESYNC m;
    m.spindle = spindle;
    m.feed_per_revolution = fpr_mu;
    m.velocity_mode = velocity_mode ? 1 : 0;
    list_.append(m, 0);
}

// G61.1 -> STOP, G61 -> EXACT, G64 -> BLEND with its P tolerance; sent only when changed.
void TaskCanon::set_motion_control_mode(CanonMotionMode mode, double tol)
{
    double tol_mu = to_mu(tol);
    if (mode == motion_mode_ && tol_mu == tolerance_) return;
    flush();
    motion_mode_ = mode;
    tolerance_ = tol_mu;
    EMC_TRAJ_SET_TERM_COND m;
    m.cond = mode == CANON_EXACT_STOP ? EMC_TRAJ_TERM_COND_STOP
           : mode == CANON_EXACT_PATH ? EMC_TRAJ_TERM_COND_EXACT : EMC_TRAJ_TERM_COND_BLEND;
    m.tolerance = tol_mu;
    m.planner_type = -1;
    m.scurve_peak_scale = peak_scale_;
    list_.append(m, 0);
}

// G64 R: planner type and S-curve peak scale, sent with the current term condition.
void TaskCanon::set_planner_mode(int type, double peak_scale)
{
    flush();
    planner_type_ = type;
    peak_scale_ = peak_scale;
    EMC_TRAJ_SET_TERM_COND m;
    m.cond = motion_mode_ == CANON_EXACT_STOP ? EMC_TRAJ_TERM_COND_STOP
           : motion_mode_ == CANON_EXACT_PATH ? EMC_TRAJ_TERM_COND_EXACT : EMC_TRAJ_TERM_COND_BLEND;
    m.tolerance = tolerance_;
    m.planner_type = type;
    m.scurve_peak_scale = peak_scale;
    list_.append(m, 0);
}

void TaskCanon::set_naivecam_tolerance(double tol)
{
    flush();
    naivecam_tol_ = to_mu(tol);
}

void TaskCanon::use_tool_length_offset(const CanonPose &p)
{
    flush();
    tool_ = offsets_pose(p);
    EMC_TRAJ_SET_OFFSET m;
    m.offset = tool_;
    list_.append(m, 0);
}

// State tag for a move on `line`.
state_tag_t TaskCanon::tag() const
{
    state_tag_t t = {};
    if (tagger_) tagger_(t);
    return t;
}

CanonBlockNeeds TaskCanon::take_needs()
{
    CanonBlockNeeds n = needs_;
    needs_ = CanonBlockNeeds();
    return n;
}

CanonPose TaskCanon::get_external_position()
{
    return to_program(machine_.position());
}

CanonPose TaskCanon::get_external_probe_position()
{
    return to_program(machine_.probed_position());
}

CanonUnits TaskCanon::get_external_length_unit_type()
{
    double u = cfg_.linear_units;
    if (std::fabs(u - 1.0) < 1e-9) return CANON_UNITS_MM;
    if (std::fabs(u - 0.1) < 1e-9) return CANON_UNITS_CM;
    return CANON_UNITS_INCHES;
}

int TaskCanon::get_external_digital_input(int index, int def)
{
    if (index < 0 || index >= EMCMOT_MAX_DIO) return def;
    return machine_.digital_input(index);
}

double TaskCanon::get_external_analog_input(int index, double def)
{
    if (index < 0 || index >= EMCMOT_MAX_AIO) return def;
    return machine_.analog_input(index);
}
