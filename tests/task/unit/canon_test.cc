// canon_test.cc: unit tests of the canon and translation libraries (no HAL, no NML buffers, no motion).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "motion_translate.hh"
#include "task_canon.hh"
#include "tool_table.hh"

namespace {

// A machine at rest at the origin with no tools loaded.
class FakeMachine : public CanonMachine {
public:
    EmcPose pos = {};
    EmcPose position() override { return pos; }
    EmcPose probed_position() override { return pos; }
    double probe_tripped_value() override { return 0; }
    int digital_input(int) override { return 0; }
    double analog_input(int) override { return 0; }
    int tool_slot() override { return 0; }
    int selected_tool_slot() override { return -1; }
    int tool_index(int toolno) override { return toolno == 4 ? 2 : -1; }
    bool queue_empty() override { return true; }
    int toolchanger_fault() override { return 0; }
    int toolchanger_reason() override { return 0; }
};

CanonConfig inch_mill()
{
    CanonConfig c;
    c.linear_units = 1 / 25.4;
    for (int i = 0; i < CANON_AXES; i++) {
        c.limits.vel[i] = 400;
        c.limits.acc[i] = 1000;
        c.limits.jerk[i] = 0;
    }
    return c;
}

CanonPose at(double x, double y, double z)
{
    CanonPose p;
    p.x = x; p.y = y; p.z = z;
    return p;
}

// One line per queued message.
void dump(InterpList &list)
{
    while (!list.empty()) {
        QueuedMsg q = list.pop();
        const NMLmsg *m = q.msg();
        if (auto *l = emc_msg_as<EMC_TRAJ_LINEAR_MOVE>(m))
            printf("  LINE line=%d type=%d end=(%.6g %.6g %.6g) vel=%.6g ini_maxvel=%.6g acc=%.6g\n", q.line, l->type,
                   l->end.tran.x, l->end.tran.y, l->end.tran.z, l->vel, l->ini_maxvel, l->acc);
        else if (auto *a = emc_msg_as<EMC_TRAJ_CIRCULAR_MOVE>(m))
            printf("  ARC line=%d end=(%.6g %.6g %.6g) center=(%.6g %.6g %.6g) normal=(%g %g %g) turn=%d vel=%.6g ini_maxvel=%.6g\n",
                   q.line, a->end.tran.x, a->end.tran.y, a->end.tran.z, a->center.x, a->center.y, a->center.z,
                   a->normal.x, a->normal.y, a->normal.z, a->turn, a->vel, a->ini_maxvel);
        else
            printf("  %s\n", emc_symbol_lookup(m->type));
    }
}

void test_limits()
{
    CanonConfig c = inch_mill();
    double d[CANON_AXES] = {-5, -6, 0.5};
    canon_path_limits_t p;
    canon_line_limits(d, &c.limits, &p);
    printf("diagonal rapid: vel=%.6g acc=%.6g length=%.6g jerk=%g\n", p.vel, p.acc, p.length, p.jerk);
    double r[CANON_AXES] = {0, 0, 0, 90};
    c.limits.vel[3] = 30;
    canon_line_limits(r, &c.limits, &p);
    printf("rotary only: vel=%.6g\n", p.vel);
    double h[CANON_AXES] = {0, 0, 1};
    canon_arc_limits(0, 1, 3.0, h, &c.limits, &p);
    printf("helix: vel=%.6g length=%.6g\n", p.vel, p.length);
}

void test_canon()
{
    FakeMachine machine;
    InterpList list;
    TaskCanon canon(inch_mill(), machine, list);
    canon.init_canon();
    canon.use_length_units(CANON_UNITS_INCHES);
    canon.set_feed_rate(40);
    canon.straight_feed(4, at(2, 0, 0));
    canon.straight_traverse(5, at(2, 3, 1));
    printf("feed and traverse (inch machine, inch program):\n");
    dump(list);
    canon.use_length_units(CANON_UNITS_MM);
    canon.straight_traverse(6, at(25.4, 0, 0));
    printf("mm program on an inch machine:\n");
    dump(list);
    canon.use_length_units(CANON_UNITS_INCHES);
    canon.set_naivecam_tolerance(0.01);
    canon.straight_feed(7, at(2, 0, 0));
    canon.straight_feed(8, at(3, 0.005, 0));
    canon.straight_feed(9, at(4, 0, 0));
    canon.straight_feed(10, at(4, 1, 0));
    canon.flush();
    printf("naive-CAM merge within Q0.01 (three collinear feeds -> one):\n");
    dump(list);
    canon.set_naivecam_tolerance(0);
    canon.arc_feed(11, 4, 3, 4, 2, 1, 0, 0, 0, 0, 0, 0, 0);
    canon.arc_feed(12, 5, 2, 4, 2, -2, -1, 0, 0, 0, 0, 0, 0);
    printf("arcs (CCW quarter, CW with one extra turn and a helix):\n");
    dump(list);
    CanonPose g5x = at(1, 0, 0);
    canon.set_g5x_offset(2, g5x);
    canon.set_xy_rotation(90);
    EmcPose m = canon.to_machine(at(1, 0, 0));
    CanonPose back = canon.to_program(m);
    printf("G55 X1 + rotation 90: machine (%.4f %.4f) back (%.4f %.4f) g5x_index=%d\n", m.tran.x, m.tran.y,
           back.x, back.y, canon.g5x_index());
    dump(list);
    canon.select_tool(4);
    canon.change_tool();
    canon.wait_input(3, 1, 3, 2.0);
    CanonBlockNeeds needs = canon.take_needs();
    printf("tool and M66: tool_data=%d wait_input=%d index=%d digital=%d\n", needs.tool_data, needs.wait_input,
           needs.wait_index, needs.wait_digital);
    dump(list);
}

void test_translate()
{
    MachineConfig cfg;
    cfg.joints = 3;
    cfg.joint.assign(3, JointConfig());
    cfg.joint[1].home_sequence = 0;
    cfg.joint[1].home_use_index = true;
    cfg.joint[1].volatile_home = true;
    MotionTranslator xl(cfg);
    MotionCommands out;
    xl.startup(out);
    printf("startup stream: %zu commands, first %s, last %s\n", out.size(), emcmot_command_name(out.front().command),
           emcmot_command_name(out.back().command));
    for (const emcmot_command_t &c : out)
        if (c.command == EMCMOT_SET_JOINT_HOMING_PARAMS && c.joint == 1)
            printf("joint 1 homing: flags=0x%02x sequence=%d volatile=%d\n", c.home_flags, c.home_sequence, c.volatile_home);
    out.clear();
    EMC_JOG_INCR jog;
    jog.jjogmode = EMC_JOG_AXIS;
    jog.joint_or_axis = 2;
    jog.vel = -1.5;
    jog.incr = 0.1;
    xl.translate(jog, out);
    printf("axis jog: %s joint=%d axis=%d vel=%g offset=%g\n", emcmot_command_name(out[0].command), out[0].joint,
           out[0].axis, out[0].vel, out[0].offset);
    out.clear();
    EMC_JOINT_SET_MAX_POSITION_LIMIT lim;
    lim.joint = 0;
    lim.limit = 5;
    xl.translate(lim, out);
    printf("max limit keeps min: min=%g max=%g\n", out[0].min_limit, out[0].max_limit);
    out.clear();
    EMC_TASK_SET_MODE mode;
    printf("task message is not for motion: %d\n", xl.translate(mode, out));
}

void test_tool_table()
{
    char dir[] = "/tmp/canon_test.XXXXXX";
    if (!mkdtemp(dir)) return;
    std::string path = std::string(dir) + "/t.tbl";
    FILE *f = fopen(path.c_str(), "w");
    fprintf(f, "; header\nT1 P1 D0.125 Z+0.511 ;first\nT7 P3 X-1 Z2 Q3 I10 J80 ;lathe\nT9 Q1\nT3 P2 R5\n");
    fclose(f);
    ToolTable t(false);
    std::vector<std::string> errors;
    bool ok = t.load(path, &errors);
    printf("load ok=%d rows=%d errors:\n", ok, t.size());
    for (const std::string &e : errors) printf("  %s\n", e.substr(e.find("t.tbl")).c_str());
    std::string err;
    t.save(path, &err);
    ToolTable again(false);
    again.load(path, &errors);
    printf("round trip rows=%d T7 index=%d x=%g orientation=%d comment='%s'\n", again.size(), again.find(7),
           again.at(again.find(7)).offset.tran.x, again.at(again.find(7)).orientation, again.at(again.find(7)).comment);
    FILE *g = fopen(path.c_str(), "r");
    char line[256];
    while (fgets(line, sizeof line, g)) printf("  %s", line);
    fclose(g);
    unlink(path.c_str());
    rmdir(dir);
}

}  // namespace

int main()
{
    test_limits();
    test_canon();
    test_translate();
    test_tool_table();
    return 0;
}
