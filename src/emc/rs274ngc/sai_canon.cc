// sai_canon.cc: printed canon calls of the standalone interpreter, in LinuxCNC rs274's exact formats.
#include "sai_canon.hh"

#include <cmath>
#include <cstdarg>
#include <cstring>

// Append v formatted like printf("%.4f"); exact (fast path away from rounding ties).
char *format_fixed4(char *buf, double v)
{
    if (!std::isfinite(v)) return buf + sprintf(buf, "%.4f", v);
    double a = std::fabs(v);
    if (a < 1e6) {
        double t = a * 10000.0;
        unsigned long long whole = (unsigned long long)t;
        double frac = t - (double)whole;
        if (std::fabs(frac - 0.5) > 1e-4) {
            unsigned long long n = whole + (frac > 0.5 ? 1 : 0);
            unsigned ip = (unsigned)(n / 10000), fp = (unsigned)(n % 10000);
            char tmp[32];
            int len = 0;
            for (int i = 0; i < 4; i++) { tmp[len++] = (char)('0' + fp % 10); fp /= 10; }
            tmp[len++] = '.';
            do { tmp[len++] = (char)('0' + ip % 10); ip /= 10; } while (ip);
            if (std::signbit(v)) *buf++ = '-';
            while (len) *buf++ = tmp[--len];
            *buf = 0;
            return buf;
        }
    }
    return buf + sprintf(buf, "%.4f", v);
}

// Write one call line: counter, N marker, text.
void SaiCanon::emit(const char *text)
{
    emit(text, strlen(text));
}

// Write one call line of known length.
void SaiCanon::emit(const char *text, size_t len)
{
    if (!out_) return;
    char head[64];
    int n = counter_text(head, ++counter_);
    const std::string &l = *line_;
    size_t i = 0;
    while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == '/')) i++;
    if (i < l.size() && (l[i] == 'n' || l[i] == 'N')) {
        head[n++] = 'N';
        size_t k = i + 1, digits = 0;
        while (k < l.size() && l[k] >= '0' && l[k] <= '9' && n < 40) { head[n++] = l[k++]; digits++; }
        while (digits++ < 6) head[n++] = ' ';
    } else {
        memcpy(head + n, "N..... ", 7);
        n += 7;
    }
    if (n + len + 1 <= sizeof line_buf_) {
        memcpy(line_buf_, head, n);
        memcpy(line_buf_ + n, text, len);
        line_buf_[n + len] = '\n';
        fwrite(line_buf_, 1, n + len + 1, out_);
        return;
    }
    fwrite(head, 1, n, out_);
    fwrite(text, 1, len, out_);
    fputc('\n', out_);
}

// "%5ld " of the call counter.
int SaiCanon::counter_text(char *buf, long v)
{
    if (v < 0) return sprintf(buf, "%5ld ", v);
    char digits[24];
    int nd = 0;
    do { digits[nd++] = (char)('0' + v % 10); v /= 10; } while (v);
    int n = 0;
    while (n < 5 - nd) buf[n++] = ' ';
    while (nd) buf[n++] = digits[--nd];
    buf[n++] = ' ';
    return n;
}

// printf-style emit (any length).
void SaiCanon::emitf(const char *fmt, ...)
{
    if (!out_) return;
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (n < (int)sizeof buf) {
        emit(buf);
        return;
    }
    std::string big((size_t)n + 1, '\0');
    va_start(ap, fmt);
    vsnprintf(&big[0], big.size(), fmt, ap);
    va_end(ap);
    emit(big.c_str());
}

// NAME(prefix v1<sep>v2...) with up to 9 values, each "%.4f".
void SaiCanon::emit_values(const char *name, const double *v, int count, const char *sep)
{
    if (!out_) return;
    char text[64 + 9 * (FIXED4_MAX + 4)];
    char *e = stpcpy(text, name);
    for (int i = 0; i < count && i < 9; i++) {
        if (i) e = stpcpy(e, sep);
        e = format_fixed4(e, v[i]);
    }
    *e++ = ')';
    *e = 0;
    emit(text, (size_t)(e - text));
}

// NAME(x<sep>y...) with count pose values.
void SaiCanon::emit_pose(const char *name, int count, const CanonPose &p, const char *sep)
{
    const double v[9] = {p.x, p.y, p.z, p.a, p.b, p.c, p.u, p.v, p.w};
    std::string prefix = std::string(name) + "(";
    emit_values(prefix.c_str(), v, count, sep);
}

// Remember the last commanded point (program coordinates).
void SaiCanon::track(const CanonPose &p) { pos_ = p; }

// Print the SET_G5X_OFFSET call.
void SaiCanon::set_g5x_offset(int origin, const CanonPose &p)
{
    char name[48];
    snprintf(name, sizeof name, "SET_G5X_OFFSET(%d, ", origin);
    const double v[6] = {p.x, p.y, p.z, p.a, p.b, p.c};
    emit_values(name, v, 6, ", ");
}
// Print the SET_G92_OFFSET call.
void SaiCanon::set_g92_offset(const CanonPose &p) { emit_pose("SET_G92_OFFSET", 6, p, ", "); }
// Print the SET_XY_ROTATION call.
void SaiCanon::set_xy_rotation(double deg) { emitf("SET_XY_ROTATION(%.4f)", deg); }
// Print the USE_LENGTH_UNITS call.
void SaiCanon::use_length_units(CanonUnits u)
{
    units_ = u;
    emit(u == CANON_UNITS_INCHES ? "USE_LENGTH_UNITS(CANON_UNITS_INCHES)"
         : u == CANON_UNITS_MM   ? "USE_LENGTH_UNITS(CANON_UNITS_MM)"
                                 : "USE_LENGTH_UNITS(CANON_UNITS_CM)");
}
// Print the SELECT_PLANE call.
void SaiCanon::select_plane(CanonPlane p)
{
    emit(p == CANON_PLANE_XY ? "SELECT_PLANE(CANON_PLANE_XY)"
         : p == CANON_PLANE_YZ ? "SELECT_PLANE(CANON_PLANE_YZ)"
         : p == CANON_PLANE_XZ ? "SELECT_PLANE(CANON_PLANE_XZ)"
                               : "SELECT_PLANE(CANON_PLANE_UNKNOWN)");
}
// Print the SET_FEED_REFERENCE call.
void SaiCanon::set_feed_reference(CanonFeedReference r)
{
    emit(r == CANON_XYZ ? "SET_FEED_REFERENCE(CANON_XYZ)" : "SET_FEED_REFERENCE(CANON_WORKPIECE)");
}
// Print the SET_FEED_MODE call.
void SaiCanon::set_feed_mode(int spindle, int mode) { emitf("SET_FEED_MODE(%d, %d)", spindle, mode); }
// Print the SET_FEED_RATE call.
void SaiCanon::set_feed_rate(double rate) { emit_values("SET_FEED_RATE(", &rate, 1, ""); }
// Print the SET_MOTION_CONTROL_MODE call.
void SaiCanon::set_motion_control_mode(CanonMotionMode m, double tol)
{
    if (m == CANON_CONTINUOUS) emitf("SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, %f)", tol);
    else if (m == CANON_EXACT_PATH) emit("SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)");
    else emit("SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP)");
}
// Print the SET_PLANNER_MODE call.
void SaiCanon::set_planner_mode(int type, double peak)
{
    emitf("SET_PLANNER_MODE(type=%d, peak_scale=%f)", type, peak);
}
// Print the SET_NAIVECAM_TOLERANCE call.
void SaiCanon::set_naivecam_tolerance(double tol) { emitf("SET_NAIVECAM_TOLERANCE(%.4f)", tol); }
// Print the STRAIGHT_TRAVERSE call.
void SaiCanon::straight_traverse(int, const CanonPose &p)
{
    emit_pose("STRAIGHT_TRAVERSE", 6, p, ", ");
    track(p);
}
// Print the STRAIGHT_FEED call.
void SaiCanon::straight_feed(int, const CanonPose &p)
{
    emit_pose("STRAIGHT_FEED", 6, p, ", ");
    track(p);
}
// Print the ARC_FEED call.
void SaiCanon::arc_feed(int, double e1, double e2, double c1, double c2, int rot, double ae,
                        double a, double b, double c, double, double, double)
{
    if (!out_) return;
    char num[FIXED4_MAX];
    std::string text = "ARC_FEED(";
    const double v1[4] = {e1, e2, c1, c2};
    for (double v : v1) {
        format_fixed4(num, v);
        text += num;
        text += ", ";
    }
    text += std::to_string(rot);
    const double v2[4] = {ae, a, b, c};
    for (double v : v2) {
        format_fixed4(num, v);
        text += ", ";
        text += num;
    }
    text += ')';
    emit(text.c_str());
}
// Print the TURN_PROBE_ON call.
void SaiCanon::turn_probe_on() { emit("TURN_PROBE_ON()"); }
// Print the TURN_PROBE_OFF call.
void SaiCanon::turn_probe_off() { emit("TURN_PROBE_OFF()"); }
// Probe: the sai model stops 0.01 in / 0.254 mm short of the target, toward the start.
void SaiCanon::straight_probe(int, const CanonPose &p, int)
{
    emit_pose("STRAIGHT_PROBE", 6, p, ", ");
    probe_ = p;
    double back = units_ == CANON_UNITS_INCHES ? 0.01 : 0.254;
    double dx = p.x - pos_.x, dy = p.y - pos_.y, dz = p.z - pos_.z;
    double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    CanonPose end = p;
    if (len > 0) {
        end.x -= dx / len * back;
        end.y -= dy / len * back;
        end.z -= dz / len * back;
    }
    pos_ = end;
}
// Print the RIGID_TAP call.
void SaiCanon::rigid_tap(int, double x, double y, double z, double)
{
    const double v[3] = {x, y, z};
    emit_values("RIGID_TAP(", v, 3, ", ");
}
// Print the DWELL call.
void SaiCanon::dwell(double s) { emitf("DWELL(%.4f)", s); }
// Print the NURBS_G5_FEED call.
void SaiCanon::nurbs_g5_feed(int, const std::vector<CanonNurbsPoint> &pts, unsigned, CanonPlane)
{
    emitf("NURBS_G5_FEED(%lu, ...)", (unsigned long)pts.size());
}
// Print the START_SPEED_FEED_SYNCH call.
void SaiCanon::start_speed_feed_synch(int, double f, bool v)
{
    emitf("START_SPEED_FEED_SYNC(%f,%d)", f, v ? 1 : 0);
}
// Print the STOP_SPEED_FEED_SYNCH call.
void SaiCanon::stop_speed_feed_synch() { emit("STOP_SPEED_FEED_SYNCH()"); }
// Print the FINISH call.
void SaiCanon::finish() { emit("FINISH()"); }
// Print the ON_RESET call.
void SaiCanon::on_reset() { emit("ON_RESET()"); }
// Print the SET_SPINDLE_MODE call.
void SaiCanon::set_spindle_mode(int s, double css) { emitf("SET_SPINDLE_MODE(%d %.4f)", s, css); }
// Print the SET_SPINDLE_SPEED call.
void SaiCanon::set_spindle_speed(int s, double v) { emitf("SET_SPINDLE_SPEED(%i, %.4f)", s, v); }
// Print the START_SPINDLE_CLOCKWISE call.
void SaiCanon::start_spindle_clockwise(int s) { emitf("START_SPINDLE_CLOCKWISE(%i)", s); }
// Print the START_SPINDLE_COUNTERCLOCKWISE call.
void SaiCanon::start_spindle_counterclockwise(int s)
{
    emitf("START_SPINDLE_COUNTERCLOCKWISE(%i)", s);
}
// Print the STOP_SPINDLE_TURNING call.
void SaiCanon::stop_spindle_turning(int s) { emitf("STOP_SPINDLE_TURNING(%i)", s); }
// Print the ORIENT_SPINDLE call.
void SaiCanon::orient_spindle(int s, double a, int m) { emitf("ORIENT_SPINDLE(%d, %.4f, %d)", s, a, m); }
// Print the WAIT_SPINDLE_ORIENT_COMPLETE call.
void SaiCanon::wait_spindle_orient_complete(int s, double t)
{
    emitf("SPINDLE.%i.WAIT_ORIENT_COMPLETE(%.4f)", s, t);
}
// Print the MIST_ON call.
void SaiCanon::mist_on() { emit("MIST_ON()"); }
// Print the MIST_OFF call.
void SaiCanon::mist_off() { emit("MIST_OFF()"); }
// Print the FLOOD_ON call.
void SaiCanon::flood_on() { emit("FLOOD_ON()"); }
// Print the FLOOD_OFF call.
void SaiCanon::flood_off() { emit("FLOOD_OFF()"); }
// Print the SELECT_TOOL call.
void SaiCanon::select_tool(int t) { emitf("SELECT_TOOL(%d)", t); }
// Print the CHANGE_TOOL call.
void SaiCanon::change_tool() { emit("CHANGE_TOOL()"); }
// Print the CHANGE_TOOL_NUMBER call.
void SaiCanon::change_tool_number(int i) { emitf("CHANGE_TOOL_NUMBER(%d)", i); }
// Print the RELOAD_TOOLDATA call.
void SaiCanon::reload_tooldata() { emit("RELOAD_TOOLDATA()"); }
// Print the SET_TOOL_TABLE_ENTRY call.
void SaiCanon::set_tool_table_entry(int index, const CanonTool &t)
{
    const CanonPose &o = t.offset;
    emitf("SET_TOOL_TABLE_ENTRY(%d, %d, %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f, %.4f, %.4f, %d)",
          index, t.toolno, o.x, o.y, o.z, o.a, o.b, o.c, o.u, o.v, o.w, t.frontangle,
          t.backangle, t.orientation);
}
// Print the USE_TOOL_LENGTH_OFFSET call.
void SaiCanon::use_tool_length_offset(const CanonPose &o)
{
    emitf("USE_TOOL_LENGTH_OFFSET(%.4f %.4f %.4f, %.4f %.4f %.4f, %.4f %.4f %.4f)", o.x, o.y, o.z,
          o.a, o.b, o.c, o.u, o.v, o.w);
}
// Print the ENABLE_FEED_OVERRIDE call.
void SaiCanon::enable_feed_override() { emit("ENABLE_FEED_OVERRIDE()"); }
// Print the DISABLE_FEED_OVERRIDE call.
void SaiCanon::disable_feed_override() { emit("DISABLE_FEED_OVERRIDE()"); }
// Print the ENABLE_SPEED_OVERRIDE call.
void SaiCanon::enable_speed_override(int s) { emitf("ENABLE_SPEED_OVERRIDE(%i)", s); }
// Print the DISABLE_SPEED_OVERRIDE call.
void SaiCanon::disable_speed_override(int s) { emitf("DISABLE_SPEED_OVERRIDE(%i)", s); }
// Print the ENABLE_ADAPTIVE_FEED call.
void SaiCanon::enable_adaptive_feed() { emit("ENABLE_ADAPTIVE_FEED()"); }
// Print the DISABLE_ADAPTIVE_FEED call.
void SaiCanon::disable_adaptive_feed() { emit("DISABLE_ADAPTIVE_FEED()"); }
// Print the ENABLE_FEED_HOLD call.
void SaiCanon::enable_feed_hold() { emit("ENABLE_FEED_HOLD()"); }
// Print the DISABLE_FEED_HOLD call.
void SaiCanon::disable_feed_hold() { emit("DISABLE_FEED_HOLD()"); }
// Print the SET_MOTION_OUTPUT_BIT call.
void SaiCanon::set_motion_output_bit(int n) { emitf("SET_MOTION_OUTPUT_BIT(%d)", n); }
// Print the CLEAR_MOTION_OUTPUT_BIT call.
void SaiCanon::clear_motion_output_bit(int n) { emitf("CLEAR_MOTION_OUTPUT_BIT(%d)", n); }
// Print the SET_AUX_OUTPUT_BIT call.
void SaiCanon::set_aux_output_bit(int n) { emitf("SET_AUX_OUTPUT_BIT(%d)", n); }
// Print the CLEAR_AUX_OUTPUT_BIT call.
void SaiCanon::clear_aux_output_bit(int n) { emitf("CLEAR_AUX_OUTPUT_BIT(%d)", n); }
// Print the SET_MOTION_OUTPUT_VALUE call.
void SaiCanon::set_motion_output_value(int n, double v) { emitf("SET_MOTION_OUTPUT_VALUE(%d,%f)", n, v); }
// Print the SET_AUX_OUTPUT_VALUE call.
void SaiCanon::set_aux_output_value(int n, double v) { emitf("SET_AUX_OUTPUT_VALUE(%d,%f)", n, v); }
// Print the COMMENT call.
void SaiCanon::comment(const std::string &t) { emitf("COMMENT(\"%s\")", t.c_str()); }
// Print the MESSAGE call.
void SaiCanon::message(const std::string &t) { emitf("MESSAGE(\"%s\")", t.c_str()); }
void SaiCanon::canon_error(const std::string &t) { emitf("CANON_ERROR(%s)", t.c_str()); }
// Print the LOG call.
void SaiCanon::log(const std::string &t) { emitf("LOG(\"%s\")", t.c_str()); }
// Print the LOGOPEN call.
void SaiCanon::logopen(const std::string &t) { emitf("LOGOPEN(\"%s\")", t.c_str()); }
// Print the LOGAPPEND call.
void SaiCanon::logappend(const std::string &t) { emitf("LOGAPPEND(\"%s\")", t.c_str()); }
// Print the LOGCLOSE call.
void SaiCanon::logclose() { emit("LOGCLOSE()"); }
// Print the PROGRAM_STOP call.
void SaiCanon::program_stop() { emit("PROGRAM_STOP()"); }
// Print the OPTIONAL_PROGRAM_STOP call.
void SaiCanon::optional_program_stop() { emit("OPTIONAL_PROGRAM_STOP()"); }
// Print the PALLET_SHUTTLE call.
void SaiCanon::pallet_shuttle() { emit("PALLET_SHUTTLE()"); }
// Print the PROGRAM_END call.
void SaiCanon::program_end() { emit("PROGRAM_END()"); }
