// estimate_report.cc: adding up the simulated servo cycles and printing the estimate.
#include "estimate_report.hh"

#include <cstring>

namespace {

// Share of the programmed feed under which a cycle counts as slow.
const double SLOW_SHARE = 0.9;

// "1h 02m 03.4s" style duration.
std::string duration(double s)
{
    char buf[64];
    int h = (int)(s / 3600.0), m = (int)((s - 3600.0 * h) / 60.0);
    double sec = s - 3600.0 * h - 60.0 * m;
    if (h > 0) snprintf(buf, sizeof buf, "%dh %02dm %04.1fs", h, m, sec);
    else if (m > 0) snprintf(buf, sizeof buf, "%dm %04.1fs", m, sec);
    else snprintf(buf, sizeof buf, "%.3fs", sec);
    return buf;
}

bool moved(const EmcPose &a, const EmcPose &b) { return memcmp(&a, &b, sizeof a) != 0; }

}  // namespace

void EstimateReport::add(const SimSample &s, int tool)
{
    if (moved(s.pos, prev_)) {
        if (first_move_ < 0) first_move_ = cycles_;
        last_move_ = cycles_;
    }
    prev_ = s.pos;
    cycles_++;
    if (s.line > 0) line_ = s.line;
    per_tool_[tool]++;
    per_line_[line_ > 0 ? line_ : 1]++;
    bool feed = s.motion_type == TP_MOTION_FEED || s.motion_type == TP_MOTION_ARC;
    if (feed && s.requested_vel > 0.0) {
        feed_cycles_++;
        if (s.vel < SLOW_SHARE * s.requested_vel) slow_cycles_++;
    }
    if (keep_path_ && s.motion_type != 0)
        path_.push_back({(float)s.pos.tran.x, (float)s.pos.tran.y, (float)s.vel,
                         s.motion_type == TP_MOTION_TRAVERSE});
}

long EstimateReport::motion_cycles() const
{
    return first_move_ < 0 ? 0 : (last_move_ - first_move_ + 1) * servo_per_traj_;
}

void EstimateReport::print(FILE *f, const std::string &program, int ranges) const
{
    double total = seconds();
    fprintf(f, "program: %s\n", program.c_str());
    fprintf(f, "total cycle time: %s (%.3f s, %ld servo cycles of %.3f ms)\n", duration(total).c_str(), total,
            cycles_ * servo_per_traj_, 1e3 * period_ / servo_per_traj_);
    fprintf(f, "in motion: %ld servo cycles (first to last cycle that moved)\n", motion_cycles());
    double slow = feed_cycles_ ? 100.0 * slow_cycles_ / feed_cycles_ : 0.0;
    fprintf(f, "feed moves: %s, %.1f %% of it below 90 %% of the programmed feed\n",
            duration(feed_cycles_ * period_).c_str(), slow);
    fprintf(f, "time per tool:\n");
    for (const auto &t : per_tool_)
        fprintf(f, "  %s %-6d %12s  %5.1f %%\n", t.first > 0 ? "T" : " ", t.first, duration(t.second * period_).c_str(),
                total > 0 ? 100.0 * t.second * period_ / total : 0.0);
    int last = last_line_ > 0 ? last_line_ : (per_line_.empty() ? 0 : per_line_.rbegin()->first);
    if (ranges < 1) ranges = 1;
    int width = (last + ranges - 1) / ranges;
    if (width < 1) width = 1;
    fprintf(f, "time per line range:\n");
    for (int lo = 1; lo <= last; lo += width) {
        long n = 0;
        for (auto it = per_line_.lower_bound(lo); it != per_line_.end() && it->first < lo + width; ++it) n += it->second;
        fprintf(f, "  lines %6d-%-6d %12s  %5.1f %%\n", lo, lo + width - 1, duration(n * period_).c_str(),
                total > 0 ? 100.0 * n * period_ / total : 0.0);
    }
}
