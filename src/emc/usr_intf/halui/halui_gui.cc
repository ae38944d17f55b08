// halui_gui.cc: the GUI bridge's jog rates: gui_bridge.jog-rate(-angular) against halui.axis.jog-speed(-angular), the latest change wins.
#include "halui.hh"

namespace {

// The bridge's rate pin, read by name each cycle (the bridge may come and go).
bool bridge_rate(const char *name, double *value)
{
    hal_type_t type;
    int dir;
    hal_data_u v;
    if (hal_get_p(name, &type, &dir, &v) < 0 || type != HAL_FLOAT) return false;
    *value = v.f;
    return true;
}

// One rate: halui's pin value, the bridge's (when present), and who changed last.
struct RateSide {
    double &last_halui, &last_bridge, &rate;
    bool &bridge_won;
};

// Arbitrate one rate. When the bridge first appears its value becomes the baseline, so
// the rate does not jump until the GUI changes it.
void arbitrate(RateSide s, double halui_value, bool have_bridge, double bridge_value, bool first_sight)
{
    if (!have_bridge) {
        s.bridge_won = false;
    } else if (first_sight) {
        s.last_bridge = bridge_value;
    } else if (bridge_value != s.last_bridge) {
        s.last_bridge = bridge_value;
        s.bridge_won = true;
    }
    if (halui_value != s.last_halui) s.bridge_won = false;
    s.last_halui = halui_value;
    s.rate = s.bridge_won ? s.last_bridge : halui_value;
}

} // namespace

// The effective jog rates of this cycle, also published on halui.gui.jog-rate(-angular).
void halui_gui(Halui &h)
{
    GuiJogRate &g = h.gui_rate;
    double bridge = 0, bridge_ang = 0;
    bool have = bridge_rate("gui_bridge.jog-rate", &bridge);
    bool have_ang = bridge_rate("gui_bridge.jog-rate-angular", &bridge_ang);
    bool first = (have || have_ang) && !g.bridge_seen;
    g.bridge_seen = have || have_ang;
    arbitrate({g.last_halui, g.last_bridge, g.rate, g.bridge_won}, **h.pins.axis_jog_speed, have,
              bridge, first);
    arbitrate({g.last_halui_ang, g.last_bridge_ang, g.rate_ang, g.bridge_won_ang},
              **h.pins.axis_jog_speed_angular, have_ang, bridge_ang, first);
    **h.pins.gui.jog_rate = g.rate;
    **h.pins.gui.jog_rate_angular = g.rate_ang;
}
