// halui_pins.cc: creating halui's HAL pins, one small function per group, with LinuxCNC's names, types and directions.
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "halui.hh"

namespace {

// Makes pins of one component; the first failure is reported and remembered.
class PinMaker {
public:
    explicit PinMaker(int comp_id) : comp_id_(comp_id) {}
    int status() const { return rc_; }

    hal_bit_t **bit(hal_pin_dir_t dir, bool dflt, const std::string &name)
    {
        hal_bit_t **ref = nullptr;
        check(hal_pin_new_bool(comp_id_, dir, &ref, dflt, "%s", name.c_str()), name);
        return ref;
    }
    hal_float_t **real(hal_pin_dir_t dir, double dflt, const std::string &name)
    {
        hal_float_t **ref = nullptr;
        check(hal_pin_new_real(comp_id_, dir, &ref, dflt, "%s", name.c_str()), name);
        return ref;
    }
    hal_s32_t **s32(hal_pin_dir_t dir, const std::string &name)
    {
        hal_s32_t **ref = nullptr;
        check(hal_pin_new_si32(comp_id_, dir, &ref, 0, "%s", name.c_str()), name);
        return ref;
    }
    hal_u32_t **u32(hal_pin_dir_t dir, const std::string &name)
    {
        hal_u32_t **ref = nullptr;
        check(hal_pin_new_ui32(comp_id_, dir, &ref, 0, "%s", name.c_str()), name);
        return ref;
    }
    // An input bit that acts on its edges.
    BitIn button(const std::string &name)
    {
        BitIn b;
        b.ref = bit(HAL_IN, false, name);
        return b;
    }

private:
    void check(int rc, const std::string &name)
    {
        if (rc >= 0 || rc_ < 0) return;
        fprintf(stderr, "halui: cannot create pin %s: %s\n", name.c_str(), strerror(-rc));
        rc_ = rc;
    }
    int comp_id_;
    int rc_ = 0;
};

// printf into a std::string.
__attribute__((format(printf, 1, 2))) std::string fmt(const char *f, ...)
{
    char buf[HAL_NAME_LEN + 1];
    va_list ap;
    va_start(ap, f);
    vsnprintf(buf, sizeof buf, f, ap);
    va_end(ap);
    return buf;
}

// <prefix>.count-enable (TRUE), .counts, .direct-value, .scale, .increase, .decrease,
// .reset (unless has_reset is false) and .value.
OverridePins override_pins(PinMaker &m, const std::string &prefix, bool has_reset)
{
    OverridePins p;
    p.count_enable = m.bit(HAL_IN, true, prefix + ".count-enable");
    p.counts = m.s32(HAL_IN, prefix + ".counts");
    p.direct_value = m.bit(HAL_IN, false, prefix + ".direct-value");
    p.scale = m.real(HAL_IN, 0.0, prefix + ".scale");
    p.increase = m.bit(HAL_IN, false, prefix + ".increase");
    p.decrease = m.bit(HAL_IN, false, prefix + ".decrease");
    p.reset = has_reset ? m.bit(HAL_IN, false, prefix + ".reset") : nullptr;
    p.value = m.real(HAL_OUT, 0.0, prefix + ".value");
    return p;
}

// <prefix>.plus/.minus/.increment-plus/.increment-minus/.increment (and .analog).
void jog_pins(PinMaker &m, const std::string &prefix, bool analog, JogPins &p)
{
    p.plus = m.button(prefix + ".plus");
    p.minus = m.button(prefix + ".minus");
    p.increment_plus = m.button(prefix + ".increment-plus");
    p.increment_minus = m.button(prefix + ".increment-minus");
    p.increment = m.real(HAL_IN, 0.0, prefix + ".increment");
    if (analog) p.analog = m.real(HAL_IN, 0.0, prefix + ".analog");
}

// <prefix>.is-homed, .has-fault, .on-soft/hard-min/max-limit, .override-limits.
void joint_status_pins(PinMaker &m, const std::string &prefix, JointStatusPins &p)
{
    p.is_homed = m.bit(HAL_OUT, false, prefix + ".is-homed");
    p.has_fault = m.bit(HAL_OUT, false, prefix + ".has-fault");
    p.on_soft_min = m.bit(HAL_OUT, false, prefix + ".on-soft-min-limit");
    p.on_soft_max = m.bit(HAL_OUT, false, prefix + ".on-soft-max-limit");
    p.on_hard_min = m.bit(HAL_OUT, false, prefix + ".on-hard-min-limit");
    p.on_hard_max = m.bit(HAL_OUT, false, prefix + ".on-hard-max-limit");
    p.override_limits = m.bit(HAL_OUT, false, prefix + ".override-limits");
}

// Machine, E-stop, modes, coolant, program, abort, homing, units.
void machine_pins(PinMaker &m, const HaluiConfig &cfg, HaluiPins &p)
{
    p.machine_on = m.button("halui.machine.on");
    p.machine_off = m.button("halui.machine.off");
    p.machine_is_on = m.bit(HAL_OUT, false, "halui.machine.is-on");
    p.units_per_mm = m.real(HAL_OUT, cfg.units_per_mm, "halui.machine.units-per-mm");
    p.estop_activate = m.button("halui.estop.activate");
    p.estop_reset = m.button("halui.estop.reset");
    p.estop_is_activated = m.bit(HAL_OUT, false, "halui.estop.is-activated");
    p.mode_manual = m.button("halui.mode.manual");
    p.mode_auto = m.button("halui.mode.auto");
    p.mode_mdi = m.button("halui.mode.mdi");
    p.mode_teleop = m.button("halui.mode.teleop");
    p.mode_joint = m.button("halui.mode.joint");
    p.mode_is_manual = m.bit(HAL_OUT, false, "halui.mode.is-manual");
    p.mode_is_auto = m.bit(HAL_OUT, false, "halui.mode.is-auto");
    p.mode_is_mdi = m.bit(HAL_OUT, false, "halui.mode.is-mdi");
    p.mode_is_teleop = m.bit(HAL_OUT, false, "halui.mode.is-teleop");
    p.mode_is_joint = m.bit(HAL_OUT, false, "halui.mode.is-joint");
    p.mist_on = m.button("halui.mist.on");
    p.mist_off = m.button("halui.mist.off");
    p.mist_is_on = m.bit(HAL_OUT, false, "halui.mist.is-on");
    p.flood_on = m.button("halui.flood.on");
    p.flood_off = m.button("halui.flood.off");
    p.flood_is_on = m.bit(HAL_OUT, false, "halui.flood.is-on");
    p.abort = m.button("halui.abort");
    if (cfg.home_sequence) p.home_all = m.button("halui.home-all");
}

// halui.program.*.
void program_pins(PinMaker &m, HaluiPins &p)
{
    p.program_run = m.button("halui.program.run");
    p.program_pause = m.button("halui.program.pause");
    p.program_resume = m.button("halui.program.resume");
    p.program_step = m.button("halui.program.step");
    p.program_stop = m.button("halui.program.stop");
    p.program_is_idle = m.bit(HAL_OUT, false, "halui.program.is-idle");
    p.program_is_running = m.bit(HAL_OUT, false, "halui.program.is-running");
    p.program_is_paused = m.bit(HAL_OUT, false, "halui.program.is-paused");
    p.optional_stop_on = m.button("halui.program.optional-stop.on");
    p.optional_stop_off = m.button("halui.program.optional-stop.off");
    p.optional_stop_is_on = m.bit(HAL_OUT, false, "halui.program.optional-stop.is-on");
    p.block_delete_on = m.button("halui.program.block-delete.on");
    p.block_delete_off = m.button("halui.program.block-delete.off");
    p.block_delete_is_on = m.bit(HAL_OUT, false, "halui.program.block-delete.is-on");
}

// halui.spindle.N.* with its override.
void spindle_pins(PinMaker &m, int n, SpindlePins &p)
{
    std::string s = fmt("halui.spindle.%d", n);
    p.start = m.button(s + ".start");
    p.stop = m.button(s + ".stop");
    p.forward = m.button(s + ".forward");
    p.reverse = m.button(s + ".reverse");
    p.increase = m.button(s + ".increase");
    p.decrease = m.button(s + ".decrease");
    p.brake_on = m.button(s + ".brake-on");
    p.brake_off = m.button(s + ".brake-off");
    p.is_on = m.bit(HAL_OUT, false, s + ".is-on");
    p.runs_forward = m.bit(HAL_OUT, false, s + ".runs-forward");
    p.runs_backward = m.bit(HAL_OUT, false, s + ".runs-backward");
    p.brake_is_on = m.bit(HAL_OUT, false, s + ".brake-is-on");
    p.override = override_pins(m, s + ".override", true);
}

// halui.joint.N.*, halui.joint.selected.* and the joint jog settings.
void joint_pins(PinMaker &m, const HaluiConfig &cfg, HaluiPins &p)
{
    for (int j = 0; j < cfg.joints; j++) {
        std::string s = fmt("halui.joint.%d", j);
        JointPins &jp = p.joint[j];
        jp.select = m.button(s + ".select");
        jp.is_selected = m.bit(HAL_OUT, false, s + ".is-selected");
        jp.home = m.button(s + ".home");
        jp.unhome = m.button(s + ".unhome");
        jog_pins(m, s, true, jp.jog);
        joint_status_pins(m, s, jp.status);
    }
    p.joint_selected = m.u32(HAL_OUT, "halui.joint.selected");
    p.joint_selected_home = m.button("halui.joint.selected.home");
    p.joint_selected_unhome = m.button("halui.joint.selected.unhome");
    jog_pins(m, "halui.joint.selected", false, p.joint_selected_jog);
    joint_status_pins(m, "halui.joint.selected", p.joint_selected_status);
    p.joint_jog_speed = m.real(HAL_IN, 0.0, "halui.joint.jog-speed");
    p.joint_jog_deadband = m.real(HAL_IN, 0.0, "halui.joint.jog-deadband");
}

// halui.axis.L.* for the configured axes, halui.axis.selected.* and the axis jog settings.
void axis_pins(PinMaker &m, const HaluiConfig &cfg, HaluiPins &p)
{
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++) {
        if (!(cfg.axis_mask & (1u << a))) continue;
        std::string s = fmt("halui.axis.%c", HALUI_AXIS_LETTERS[a]);
        AxisPins &ap = p.axis[a];
        ap.select = m.button(s + ".select");
        ap.is_selected = m.bit(HAL_OUT, false, s + ".is-selected");
        jog_pins(m, s, true, ap.jog);
        ap.pos_commanded = m.real(HAL_OUT, 0.0, s + ".pos-commanded");
        ap.pos_feedback = m.real(HAL_OUT, 0.0, s + ".pos-feedback");
        ap.pos_relative = m.real(HAL_OUT, 0.0, s + ".pos-relative");
    }
    p.axis_selected = m.u32(HAL_OUT, "halui.axis.selected");
    jog_pins(m, "halui.axis.selected", false, p.axis_selected_jog);
    p.axis_jog_speed = m.real(HAL_IN, 0.0, "halui.axis.jog-speed");
    p.axis_jog_speed_angular = m.real(HAL_IN, 0.0, "halui.axis.jog-speed-angular");
    p.axis_jog_deadband = m.real(HAL_IN, 0.0, "halui.axis.jog-deadband");
}

// halui.tool.*, halui.mdi-command-NN and halui.halui-mdi-is-running.
void tool_and_mdi_pins(PinMaker &m, const HaluiConfig &cfg, HaluiPins &p)
{
    p.tool_number = m.u32(HAL_OUT, "halui.tool.number");
    p.tool_diameter = m.real(HAL_OUT, 0.0, "halui.tool.diameter");
    for (int a = 0; a < EMCMOT_MAX_AXIS; a++)
        if (cfg.axis_mask & (1u << a))
            p.tool_length_offset[a] = m.real(HAL_OUT, 0.0, fmt("halui.tool.length_offset.%c", HALUI_AXIS_LETTERS[a]));
    for (size_t i = 0; i < cfg.mdi_commands.size(); i++)
        p.mdi_command.push_back(m.button(fmt("halui.mdi-command-%02zu", i)));
    if (!cfg.mdi_commands.empty()) p.mdi_is_running = m.bit(HAL_OUT, false, "halui.halui-mdi-is-running");
}

} // namespace

// All of halui's pins.
int halui_make_pins(int comp_id, const HaluiConfig &cfg, HaluiPins &p)
{
    PinMaker m(comp_id);
    machine_pins(m, cfg, p);
    program_pins(m, p);
    p.feed_override = override_pins(m, "halui.feed-override", true);
    p.rapid_override = override_pins(m, "halui.rapid-override", true);
    p.max_velocity = override_pins(m, "halui.max-velocity", false);
    for (int s = 0; s < cfg.spindles; s++) spindle_pins(m, s, p.spindle[s]);
    joint_pins(m, cfg, p);
    axis_pins(m, cfg, p);
    tool_and_mdi_pins(m, cfg, p);
    if (m.status() < 0) return m.status();
    return halui_make_gui_pins(comp_id, cfg, p.gui);
}

// halui.gui.*: requests the bridge forwards (halui only owns them) and the jog rates.
int halui_make_gui_pins(int comp_id, const HaluiConfig &cfg, GuiPins &g)
{
    PinMaker m(comp_id);
    g.cycle_start = m.bit(HAL_IN, false, "halui.gui.cycle-start");
    g.cycle_pause = m.bit(HAL_IN, false, "halui.gui.cycle-pause");
    for (int k = 0; k < HALUI_GUI_SOFTKEYS; k++) g.softkey[k] = m.bit(HAL_IN, false, fmt("halui.gui.softkey.%02d", k));
    g.response_ok = m.bit(HAL_IN, false, "halui.gui.response.ok");
    g.response_cancel = m.bit(HAL_IN, false, "halui.gui.response.cancel");
    g.reload_preview = m.bit(HAL_IN, false, "halui.gui.reload-preview");
    g.shutdown = m.bit(HAL_IN, false, "halui.gui.shutdown");
    for (const std::string &name : cfg.gui_mdi_names)
        g.mdi_command.push_back(m.bit(HAL_IN, false, "halui.gui.mdi-command." + name));
    g.jog_rate = m.real(HAL_OUT, 0.0, "halui.gui.jog-rate");
    g.jog_rate_angular = m.real(HAL_OUT, 0.0, "halui.gui.jog-rate-angular");
    return m.status();
}
