// task_canon_moves.cc: TaskCanon moves: traverses, feeds with naive-CAM merging, arcs, probes, rigid taps, NURBS.
#include "task_canon.hh"

#include <cmath>

namespace {

// Pose as an array X Y Z A B C U V W.
void pose_array(const EmcPose &p, double out[CANON_AXES])
{
    out[0] = p.tran.x; out[1] = p.tran.y; out[2] = p.tran.z;
    out[3] = p.a; out[4] = p.b; out[5] = p.c;
    out[6] = p.u; out[7] = p.v; out[8] = p.w;
}

// b - a per axis.
void pose_delta(const EmcPose &a, const EmcPose &b, double d[CANON_AXES])
{
    double pa[CANON_AXES], pb[CANON_AXES];
    pose_array(a, pa);
    pose_array(b, pb);
    for (int i = 0; i < CANON_AXES; i++) d[i] = pb[i] - pa[i];
}

// Distance of point q from the segment a-b (all nine axes).
double segment_distance(const EmcPose &a, const EmcPose &b, const EmcPose &q)
{
    double ab[CANON_AXES], aq[CANON_AXES];
    pose_delta(a, b, ab);
    pose_delta(a, q, aq);
    double len2 = 0, dot = 0;
    for (int i = 0; i < CANON_AXES; i++) { len2 += ab[i] * ab[i]; dot += ab[i] * aq[i]; }
    double t = len2 > 0 ? dot / len2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    double d2 = 0;
    for (int i = 0; i < CANON_AXES; i++) { double e = aq[i] - t * ab[i]; d2 += e * e; }
    return std::sqrt(d2);
}

// True when only rotary axes move.
bool rotary_only(const double d[CANON_AXES])
{
    const double tiny = 1e-12;
    for (int i : {0, 1, 2, 6, 7, 8})
        if (std::fabs(d[i]) > tiny) return false;
    return std::fabs(d[3]) > tiny || std::fabs(d[4]) > tiny || std::fabs(d[5]) > tiny;
}

}  // namespace

// Requested path speed of a feed move (mu/s; G95: the ceiling, motion follows the spindle).
double TaskCanon::move_feed_vel() const
{
    return feed_;
}

// Queue one straight move of motion type `type` to end; feed_vel < 0 = rapid.
void TaskCanon::queue_line(int line, const EmcPose &end, int type, double feed_vel, const state_tag_t *t)
{
    double d[CANON_AXES];
    pose_delta(end_, end, d);
    canon_path_limits_t lim;
    canon_line_limits(d, &cfg_.limits, &lim);
    EMC_TRAJ_LINEAR_MOVE m;
    m.end = end;
    m.type = type;
    m.ini_maxvel = lim.vel;
    m.acc = lim.acc;
    double vel = feed_vel;
    if (feed_vel < 0 || (feed_mode_ == 1 && type == EMC_MOTION_TYPE_FEED)) vel = lim.vel;
    else if (rotary_only(d)) vel = feed_prog_ / 60.0 * cfg_.angular_units;
    m.vel = vel < lim.vel ? vel : lim.vel;
    m.feed_mode = feed_mode_;
    m.tag = t ? *t : tag();
    m.tag.line_number = line;
    list_.append(m, line);
    end_ = end;
}

void TaskCanon::straight_traverse(int line, const CanonPose &p)
{
    flush();
    queue_line(line, to_machine(p), EMC_MOTION_TYPE_TRAVERSE, -1);
}

void TaskCanon::straight_feed(int line, const CanonPose &p)
{
    feed_chain(line, to_machine(p));
}

// Merge collinear feeds within the naive-CAM tolerance (G64 Q) into the held move.
void TaskCanon::feed_chain(int line, const EmcPose &end)
{
    if (!chain_.empty() && chain_accepts(end)) {
        chain_.push_back(end);
        chain_line_ = line;
        chain_tag_ = tag();
        return;
    }
    flush();
    if (motion_mode_ != CANON_CONTINUOUS || naivecam_tol_ <= 0 || synced_) {
        queue_line(line, end, EMC_MOTION_TYPE_FEED, move_feed_vel());
        return;
    }
    chain_start_ = end_;
    chain_.push_back(end);
    chain_line_ = line;
    chain_tag_ = tag();
}

// The held chain extended to end stays within the tolerance of one straight line.
bool TaskCanon::chain_accepts(const EmcPose &end) const
{
    for (const EmcPose &q : chain_)
        if (segment_distance(chain_start_, end, q) > naivecam_tol_) return false;
    return true;
}

// Queue the held naive-CAM chain as one straight feed.
void TaskCanon::flush()
{
    if (chain_.empty()) return;
    EmcPose end = chain_.back();
    chain_.clear();
    end_ = chain_start_;
    queue_line(chain_line_, end, EMC_MOTION_TYPE_FEED, move_feed_vel(), &chain_tag_);
}

// Plane axis indexes (first, second, normal) of a canon plane.
static void plane_axes(CanonPlane plane, int &p1, int &p2, int &pn)
{
    switch (plane) {
    case CANON_PLANE_YZ: p1 = 1; p2 = 2; pn = 0; break;
    case CANON_PLANE_XZ: p1 = 2; p2 = 0; pn = 1; break;
    case CANON_PLANE_UV: p1 = 6; p2 = 7; pn = 8; break;
    case CANON_PLANE_VW: p1 = 7; p2 = 8; pn = 6; break;
    case CANON_PLANE_UW: p1 = 8; p2 = 6; pn = 7; break;
    default: p1 = 0; p2 = 1; pn = 2; break;
    }
}

// Set axis i of a canon pose.
static void set_axis(CanonPose &p, int i, double v)
{
    double *f[CANON_AXES] = {&p.x, &p.y, &p.z, &p.a, &p.b, &p.c, &p.u, &p.v, &p.w};
    *f[i] = v;
}

void TaskCanon::arc_feed(int line, double first_end, double second_end, double first_axis,
                         double second_axis, int rotation, double axis_end, double a, double b,
                         double c, double u, double v, double w)
{
    flush();
    int p1, p2, pn;
    plane_axes(plane_, p1, p2, pn);
    CanonPose cur = to_program(end_);
    CanonPose endp = cur;
    endp.a = a; endp.b = b; endp.c = c; endp.u = u; endp.v = v; endp.w = w;
    set_axis(endp, p1, first_end);
    set_axis(endp, p2, second_end);
    set_axis(endp, pn, axis_end);
    CanonPose cen = endp;
    set_axis(cen, p1, first_axis);
    set_axis(cen, p2, second_axis);
    EmcPose end = to_machine(endp), center = to_machine(cen);
    if (p1 >= 6) {
        arc_as_lines(line, end, center, rotation, p1, p2);
        return;
    }
    EMC_TRAJ_CIRCULAR_MOVE m;
    m.end = end;
    m.center = center.tran;
    double sign = rotation >= 0 ? 1.0 : -1.0;
    double *nrm[3] = {&m.normal.x, &m.normal.y, &m.normal.z};
    *nrm[pn] = sign;
    m.turn = (rotation >= 0 ? rotation : -rotation) - 1;
    if (m.turn < 0) m.turn = 0;
    double s[CANON_AXES], e[CANON_AXES], cc[CANON_AXES], d[CANON_AXES];
    pose_array(end_, s);
    pose_array(end, e);
    pose_array(center, cc);
    pose_delta(end_, end, d);
    double r = std::hypot(s[p1] - cc[p1], s[p2] - cc[p2]);
    double a0 = std::atan2(s[p2] - cc[p2], s[p1] - cc[p1]);
    double a1 = std::atan2(e[p2] - cc[p2], e[p1] - cc[p1]);
    double sweep = sign > 0 ? a1 - a0 : a0 - a1;
    while (sweep <= 1e-12) sweep += 2 * M_PI;
    sweep += 2 * M_PI * m.turn;
    canon_path_limits_t lim;
    canon_arc_limits(p1, p2, r * sweep, d, &cfg_.limits, &lim);
    m.type = EMC_MOTION_TYPE_ARC;
    m.ini_maxvel = lim.vel;
    m.acc = lim.acc;
    double vel = feed_mode_ == 1 ? lim.vel : move_feed_vel();
    m.vel = vel < lim.vel ? vel : lim.vel;
    m.feed_mode = feed_mode_;
    m.tag = tag();
    m.tag.line_number = line;
    list_.append(m, line);
    end_ = end;
}

// Arcs in the UV/VW/UW planes: motion's circles live in XYZ, so these go as short feeds.
void TaskCanon::arc_as_lines(int line, const EmcPose &end, const EmcPose &center, int rotation,
                                int p1, int p2)
{
    double s[CANON_AXES], e[CANON_AXES], c[CANON_AXES];
    pose_array(end_, s);
    pose_array(end, e);
    pose_array(center, c);
    double r = std::hypot(s[p1] - c[p1], s[p2] - c[p2]);
    double a0 = std::atan2(s[p2] - c[p2], s[p1] - c[p1]);
    double a1 = std::atan2(e[p2] - c[p2], e[p1] - c[p1]);
    double sign = rotation >= 0 ? 1.0 : -1.0;
    double sweep = sign > 0 ? a1 - a0 : a0 - a1;
    while (sweep <= 1e-12) sweep += 2 * M_PI;
    sweep += 2 * M_PI * ((rotation >= 0 ? rotation : -rotation) - 1);
    int n = (int)std::ceil(sweep / (M_PI / 32));
    EmcPose start = end_;
    for (int k = 1; k <= n; k++) {
        double t = (double)k / n, ang = a0 + sign * sweep * t;
        double p[CANON_AXES];
        for (int i = 0; i < CANON_AXES; i++) p[i] = s[i] + (e[i] - s[i]) * t;
        p[p1] = c[p1] + r * std::cos(ang);
        p[p2] = c[p2] + r * std::sin(ang);
        if (k == n) { p[p1] = e[p1]; p[p2] = e[p2]; }
        EmcPose q = start;
        q.tran.x = p[0]; q.tran.y = p[1]; q.tran.z = p[2];
        q.a = p[3]; q.b = p[4]; q.c = p[5]; q.u = p[6]; q.v = p[7]; q.w = p[8];
        queue_line(line, q, EMC_MOTION_TYPE_ARC, move_feed_vel());
    }
}

void TaskCanon::turn_probe_on()
{
    flush();
    EMC_TRAJ_CLEAR_PROBE_TRIPPED_FLAG m;
    list_.append(m, 0);
}

void TaskCanon::straight_probe(int line, const CanonPose &p, int type)
{
    flush();
    EmcPose end = to_machine(p);
    double d[CANON_AXES];
    pose_delta(end_, end, d);
    canon_path_limits_t lim;
    canon_line_limits(d, &cfg_.limits, &lim);
    EMC_TRAJ_PROBE m;
    m.pos = end;
    m.type = EMC_MOTION_TYPE_PROBING;
    m.probe_type = type;
    m.ini_maxvel = lim.vel;
    m.acc = lim.acc;
    double vel = move_feed_vel();
    m.vel = vel < lim.vel ? vel : lim.vel;
    m.tag = tag();
    m.tag.line_number = line;
    list_.append(m, line);
    end_ = end;
    needs_.probe = true;
}

// G33.1: tap to (x, y, z) and back; motion returns to the start by itself.
void TaskCanon::rigid_tap(int line, double x, double y, double z, double scale)
{
    flush();
    CanonPose p = to_program(end_);
    p.x = x; p.y = y; p.z = z;
    EmcPose end = to_machine(p);
    double d[CANON_AXES];
    pose_delta(end_, end, d);
    canon_path_limits_t lim;
    canon_line_limits(d, &cfg_.limits, &lim);
    EMC_TRAJ_RIGID_TAP m;
    m.pos = end;
    m.ini_maxvel = lim.vel;
    m.acc = lim.acc;
    m.vel = lim.vel;
    m.scale = scale;
    m.tag = tag();
    m.tag.line_number = line;
    list_.append(m, line);
}

void TaskCanon::dwell(double seconds)
{
    flush();
    EMC_TRAJ_DELAY m;
    m.delay = seconds;
    list_.append(m, 0);
}

// G33/G76 (position mode) or G95 (velocity mode) spindle synchronisation.
void TaskCanon::start_speed_feed_synch(int spindle, double feed_per_rev, bool velocity_mode)
{
    flush();
    synced_ = !velocity_mode;
    emit_sync(spindle, to_mu(feed_per_rev), velocity_mode);
}

void TaskCanon::stop_speed_feed_synch()
{
    flush();
    synced_ = false;
    emit_sync(feed_spindle_, 0, false);
}

// One point of a NURBS curve (de Boor on a clamped uniform knot vector), weights applied.
static void nurbs_point(const std::vector<CanonNurbsPoint> &pts, unsigned order, double u,
                        double &x, double &y)
{
    int n = (int)pts.size(), k = (int)order;
    std::vector<double> knots(n + k);
    for (int i = 0; i < n + k; i++)
        knots[i] = i < k ? 0.0 : i >= n ? 1.0 : (double)(i - k + 1) / (n - k + 1);
    int span = k - 1;
    while (span < n - 1 && u >= knots[span + 1]) span++;
    std::vector<double> dx(k), dy(k), dw(k);
    for (int j = 0; j < k; j++) {
        const CanonNurbsPoint &c = pts[span - k + 1 + j];
        dx[j] = c.x * c.weight; dy[j] = c.y * c.weight; dw[j] = c.weight;
    }
    for (int r = 1; r < k; r++)
        for (int j = k - 1; j >= r; j--) {
            int i = span - k + 1 + j;
            double den = knots[i + k - r] - knots[i];
            double a = den > 0 ? (u - knots[i]) / den : 0;
            dx[j] = (1 - a) * dx[j - 1] + a * dx[j];
            dy[j] = (1 - a) * dy[j - 1] + a * dy[j];
            dw[j] = (1 - a) * dw[j - 1] + a * dw[j];
        }
    x = dx[k - 1] / dw[k - 1];
    y = dy[k - 1] / dw[k - 1];
}

// G5/G5.1/G5.2: the curve as short straight feeds, fine enough to follow its control polygon.
void TaskCanon::nurbs_g5_feed(int line, const std::vector<CanonNurbsPoint> &pts, unsigned order,
                              CanonPlane plane)
{
    flush();
    if (pts.size() < 2 || order < 2 || order > pts.size()) return;
    double poly = 0;
    for (size_t i = 1; i < pts.size(); i++)
        poly += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    double step = 0.5 / mm_per_unit();  // about 0.5 mm per segment, in program units
    int n = (int)std::ceil(poly / step);
    if (n < 8) n = 8;
    if (n > 2000) n = 2000;
    int p1, p2, pn;
    plane_axes(plane, p1, p2, pn);
    for (int k = 1; k <= n; k++) {
        double x, y;
        nurbs_point(pts, order, k == n ? 1.0 : (double)k / n, x, y);
        CanonPose p = to_program(end_);
        set_axis(p, p1, x);
        set_axis(p, p2, y);
        queue_line(line, to_machine(p), EMC_MOTION_TYPE_FEED, move_feed_vel());
    }
}
