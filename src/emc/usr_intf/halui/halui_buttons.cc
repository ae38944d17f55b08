// halui_buttons.cc: halui's push buttons (machine, E-stop, modes, program, coolant, abort, homing, spindles) turned into NML commands.
#include <cmath>
#include <cstdio>

#include "halui.hh"

namespace {

// Seconds to wait for task to read a command before giving up on it.
const double RECEIVE_TIMEOUT_S = 1.0;
// Spindle speed of start/forward/reverse without an S word or [DISPLAY]DEFAULT_SPINDLE_SPEED.
const double FALLBACK_SPINDLE_RPM = 500.0;

// Ask task for an E-stop / machine state.
void set_state(Halui &h, int state)
{
    EMC_TASK_SET_STATE m;
    m.state = state;
    halui_send(h, m);
}

// Ask task for a mode.
void set_mode(Halui &h, int mode)
{
    EMC_TASK_SET_MODE m;
    m.mode = mode;
    halui_send(h, m);
}

// Jog axes (teleop, 1) or joints (free mode, 0).
void teleop(Halui &h, int enable)
{
    EMC_TRAJ_SET_TELEOP_ENABLE m;
    m.enable = enable;
    halui_send(h, m);
}

// A command without fields.
template <class M>
void plain(Halui &h)
{
    M m;
    halui_send(h, m);
}

// M1 stops on or off.
void optional_stop(Halui &h, int on)
{
    EMC_TASK_PLAN_SET_OPTIONAL_STOP m;
    m.state = static_cast<uint8_t>(on);
    halui_send(h, m);
}

// Block delete on or off.
void block_delete(Halui &h, int on)
{
    EMC_TASK_PLAN_SET_BLOCK_DELETE m;
    m.state = static_cast<uint8_t>(on);
    halui_send(h, m);
}

// Run the open program from its start (nothing to run while no program was opened).
void program_run(Halui &h)
{
    if (halui_machine_ready(h) && !h.client.status().task.file[0]) {
        fprintf(stderr, "halui: program.run: no program is open\n");
        return;
    }
    EMC_TASK_PLAN_RUN m;
    m.line = 0;
    halui_send(h, m);
}

// Home every joint (the homing sequence).
void home_all(Halui &h)
{
    EMC_JOINT_HOME m;
    m.joint = -1;
    halui_send(h, m);
}

// One push button: the pin and what its rising edge does.
struct Button {
    BitIn HaluiPins::*pin;
    void (*act)(Halui &);
};

// In the order they are served within a cycle: state before mode before program, so a
// panel wiring one key to halui.mode.auto and halui.program.run works.
const Button buttons[] = {
    {&HaluiPins::estop_activate, [](Halui &h) { set_state(h, EMC_TASK_STATE_ESTOP); }},
    {&HaluiPins::estop_reset, [](Halui &h) { set_state(h, EMC_TASK_STATE_ESTOP_RESET); }},
    {&HaluiPins::machine_off, [](Halui &h) { set_state(h, EMC_TASK_STATE_OFF); }},
    {&HaluiPins::machine_on, [](Halui &h) { set_state(h, EMC_TASK_STATE_ON); }},
    {&HaluiPins::abort, plain<EMC_TASK_ABORT>},
    {&HaluiPins::mode_manual, [](Halui &h) { set_mode(h, EMC_TASK_MODE_MANUAL); }},
    {&HaluiPins::mode_auto, [](Halui &h) { set_mode(h, EMC_TASK_MODE_AUTO); }},
    {&HaluiPins::mode_mdi, [](Halui &h) { set_mode(h, EMC_TASK_MODE_MDI); }},
    {&HaluiPins::mode_teleop, [](Halui &h) { teleop(h, 1); }},
    {&HaluiPins::mode_joint, [](Halui &h) { teleop(h, 0); }},
    {&HaluiPins::mist_on, plain<EMC_COOLANT_MIST_ON>},
    {&HaluiPins::mist_off, plain<EMC_COOLANT_MIST_OFF>},
    {&HaluiPins::flood_on, plain<EMC_COOLANT_FLOOD_ON>},
    {&HaluiPins::flood_off, plain<EMC_COOLANT_FLOOD_OFF>},
    {&HaluiPins::optional_stop_on, [](Halui &h) { optional_stop(h, 1); }},
    {&HaluiPins::optional_stop_off, [](Halui &h) { optional_stop(h, 0); }},
    {&HaluiPins::block_delete_on, [](Halui &h) { block_delete(h, 1); }},
    {&HaluiPins::block_delete_off, [](Halui &h) { block_delete(h, 0); }},
    {&HaluiPins::program_stop, plain<EMC_TASK_ABORT>},
    {&HaluiPins::program_pause, plain<EMC_TASK_PLAN_PAUSE>},
    {&HaluiPins::program_resume, plain<EMC_TASK_PLAN_RESUME>},
    {&HaluiPins::program_step, plain<EMC_TASK_PLAN_STEP>},
    {&HaluiPins::program_run, program_run},
    {&HaluiPins::home_all, home_all},
};

// Speed for start/forward/reverse: the programmed S word, else the configured default.
double spindle_rpm(const Halui &h)
{
    double s = std::fabs(h.client.status().task.activeSettings[2]);
    if (s > 0) return s;
    return h.cfg.default_spindle_speed > 0 ? h.cfg.default_spindle_speed : FALLBACK_SPINDLE_RPM;
}

// Start spindle n forward (1) or in reverse (-1).
void spindle_on(Halui &h, int n, int direction)
{
    EMC_SPINDLE_ON m;
    m.spindle = n;
    m.speed = direction * spindle_rpm(h);
    halui_send(h, m);
}

// A spindle command carrying only the spindle number.
template <class M>
void spindle_cmd(Halui &h, int n)
{
    M m;
    m.spindle = n;
    halui_send(h, m);
}

// INCREASE/DECREASE carry the speed the spindle should reach (motion steps by 100 rpm).
template <class M>
void spindle_step(Halui &h, int n, double step)
{
    M m;
    m.spindle = n;
    double now = h.client.status().motion.spindle[n].speed;
    m.speed = now >= 0 ? now + step : now - step;
    halui_send(h, m);
}

} // namespace

// Attached to a running task that publishes status.
bool halui_machine_ready(Halui &h)
{
    return h.client.have_status() && h.client.attach();
}

// Write a command and wait until task read it.
bool halui_send(Halui &h, const NMLmsg &msg)
{
    if (!halui_machine_ready(h)) {
        if (!h.warned_no_machine)
            fprintf(stderr, "halui: %s not sent: the machine is not running\n", emc_symbol_lookup(msg.type));
        h.warned_no_machine = true;
        return false;
    }
    h.warned_no_machine = false;
    int rc = h.client.send_and_wait(msg, UiWait::received, RECEIVE_TIMEOUT_S);
    if (rc < 0) {
        fprintf(stderr, "halui: %s: %s\n", emc_symbol_lookup(msg.type), h.client.error().c_str());
        return false;
    }
    return true;
}

// Serve every button whose edge rose since the last cycle.
void halui_buttons(Halui &h)
{
    for (const Button &b : buttons) {
        BitIn &pin = h.pins.*(b.pin);
        if (pin.ref && pin.rose()) b.act(h);
    }
}

// The spindle buttons.
void halui_spindles(Halui &h)
{
    for (int n = 0; n < h.cfg.spindles; n++) {
        SpindlePins &p = h.pins.spindle[n];
        if (p.start.rose()) spindle_on(h, n, 1);
        if (p.forward.rose()) spindle_on(h, n, 1);
        if (p.reverse.rose()) spindle_on(h, n, -1);
        if (p.stop.rose()) spindle_cmd<EMC_SPINDLE_OFF>(h, n);
        if (p.increase.rose()) spindle_step<EMC_SPINDLE_INCREASE>(h, n, 100.0);
        if (p.decrease.rose()) spindle_step<EMC_SPINDLE_DECREASE>(h, n, -100.0);
        if (p.brake_on.rose()) spindle_cmd<EMC_SPINDLE_BRAKE_ENGAGE>(h, n);
        if (p.brake_off.rose()) spindle_cmd<EMC_SPINDLE_BRAKE_RELEASE>(h, n);
    }
}
