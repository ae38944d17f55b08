// estimate_report.hh: what openemc-estimate adds up per servo cycle and prints: total time, per tool, per line range, slow share.
#ifndef ESTIMATE_REPORT_HH
#define ESTIMATE_REPORT_HH

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "sim_motion.hh"

// A point of the drawn toolpath.
struct PathPoint {
    float x, y, vel;
    bool traverse;
};

class EstimateReport {
public:
    // keep_path: record the points --png draws.
    explicit EstimateReport(bool keep_path) : keep_path_(keep_path) {}
    // period_s: one trajectory cycle; servo_per_traj: servo cycles in it.
    void set_period(double period_s, int servo_per_traj)
    {
        period_ = period_s;
        servo_per_traj_ = servo_per_traj;
    }
    // Where motion stands before the first cycle.
    void start_at(const EmcPose &p) { prev_ = p; }
    // Count one trajectory cycle with the tool in the spindle.
    void add(const SimSample &s, int tool);
    // The source line of what happens now (dwells, tool changes: no move is executing).
    void set_line(int line)
    {
        if (line > 0) line_ = line;
    }
    // The last line of the program (for the line ranges).
    void set_last_line(int line) { last_line_ = line; }
    // Print the report to f; ranges: how many line ranges.
    void print(FILE *f, const std::string &program, int ranges) const;
    const std::vector<PathPoint> &path() const { return path_; }
    // Servo cycles from the first one that moved to the last one that moved (tp-bench's count).
    long motion_cycles() const;
    long servo_cycles() const { return cycles_ * servo_per_traj_; }
    double seconds() const { return cycles_ * period_; }

private:
    double period_ = 0.001;
    int servo_per_traj_ = 1;
    bool keep_path_;
    long cycles_ = 0;
    long first_move_ = -1, last_move_ = -1;
    long feed_cycles_ = 0, slow_cycles_ = 0;
    int last_line_ = 0, line_ = 0;
    EmcPose prev_ = {};
    std::map<int, long> per_tool_;
    std::map<int, long> per_line_;
    std::vector<PathPoint> path_;
};

#endif
