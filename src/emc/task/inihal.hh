// inihal.hh: HAL component inihal, the ini.* pins (motion.md sec. 9) whose changes task forwards to motion.
#ifndef INIHAL_HH
#define INIHAL_HH

#include <string>
#include <vector>

#include "hal.h"
#include "machine_config.hh"
#include "motion_translate.hh"

class IniHal {
public:
    explicit IniHal(const MachineConfig &cfg) : cfg_(cfg) {}
    // Create the component with every pin at its INI value and make it ready (task is then
    // ready for `loadusr -Wn inihal`). false with *error.
    bool create(std::string *error);
    void destroy();
    // Compare every pin with the value last sent; append the commands for the changes.
    void check(MotionCommands &out);

private:
    struct JointPins { hal_float_t *ferror, *min_ferror, *backlash, *min_limit, *max_limit,
                       *max_velocity, *max_acceleration, *max_jerk, *home, *home_offset;
                       hal_s32_t *home_sequence; };
    struct AxisPins { hal_float_t *min_limit, *max_limit, *max_velocity, *max_acceleration, *max_jerk; };
    struct TrajPins { hal_bit_t *arc_blend_enable, *arc_blend_fallback_enable;
                      hal_s32_t *arc_blend_optimization_depth, *planner_type;
                      hal_float_t *arc_blend_gap_cycles, *arc_blend_ramp_freq, *arc_blend_tangent_kink_ratio,
                                  *default_acceleration, *default_velocity, *max_acceleration, *max_jerk,
                                  *max_velocity, *scurve_peak_scale; };
    struct Pins { JointPins joint[EMCMOT_MAX_JOINTS]; AxisPins axis[EMCMOT_MAX_AXIS]; TrajPins traj; };
    bool create_pins(std::string *error);
    void store();
    void check_joint(int j, MotionCommands &out);
    void check_axis(int a, MotionCommands &out);
    void check_traj(MotionCommands &out);

    MachineConfig cfg_;     // the values last sent
    int id_ = -1;
    Pins *pins_ = nullptr;
};

#endif
