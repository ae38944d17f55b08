/* plasmac_defs.h: plasmac's states, stop types, tools and constants (LinuxCNC's numbering). */
#ifndef PLASMAC_DEFS_H
#define PLASMAC_DEFS_H

/* Values of state-out. */
enum pm_state {
    PM_IDLE, PM_PROBE_HEIGHT, PM_PROBE_DOWN, PM_PROBE_UP, PM_ZERO_HEIGHT, PM_PIERCE_HEIGHT, PM_TORCH_ON,
    PM_ARC_OK, PM_PIERCE_DELAY, PM_PUDDLE_JUMP, PM_CUT_HEIGHT, PM_CUT_MODE_01, PM_CUT_MODE_2,
    PM_PAUSE_AT_END, PM_SAFE_HEIGHT, PM_MAX_HEIGHT, PM_END_CUT, PM_END_JOB, PM_TORCHPULSE,
    PM_PAUSED_MOTION, PM_OHMIC_TEST, PM_PROBE_TEST, PM_SCRIBING, PM_CONSUMABLE_CHANGE_ON,
    PM_CONSUMABLE_CHANGE_OFF, PM_CUT_RECOVERY_ON, PM_CUT_RECOVERY_OFF, PM_DEBUG, PM_STATES
};

/* Values of stop-type-out. */
enum pm_stop { PM_STOP_NONE, PM_STOP_STOP, PM_STOP_WAIT, PM_STOP_PAUSE };

/* Values of laser-recovery-state. */
enum pm_laser { PM_LASER_OFF, PM_LASER_SET, PM_LASER_SETTING, PM_LASER_ON, PM_LASER_RESET, PM_LASER_RESETTING };

/* The active tool. */
enum pm_tool { PM_TOOL_EMPTY, PM_TOOL_CUTTING, PM_TOOL_SCRIBE, PM_TOOL_SPOTTING };

/* What ended a probe. */
enum pm_probe { PM_PROBE_FLOAT, PM_PROBE_OHMIC };

#define PM_RING 1000              /* arc voltage samples kept */
#define PM_MM_CLEAR 1.0           /* mm above pierce height that must fit below the top */
#define PM_MM_BOTTOM 0.25         /* mm above the Z minimum where probing down stops */
#define PM_MM_SAFE_MIN 13.0       /* mm: "safe traverse height has been reduced to less than 13mm" */
#define PM_HEIGHT_OVERRIDE_STEP 0.005

/* The state names printed with debug-print. */
static const char *const pm_state_names[PM_STATES] = {
    "IDLE", "PROBE_HEIGHT", "PROBE_DOWN", "PROBE_UP", "ZERO_HEIGHT", "PIERCE_HEIGHT", "TORCH_ON", "ARC_OK",
    "PIERCE_DELAY", "PUDDLE_JUMP", "CUT_HEIGHT", "CUT_MODE_01", "CUT_MODE_2", "PAUSE_AT_END", "SAFE_HEIGHT",
    "MAX_HEIGHT", "END_CUT", "END_JOB", "TORCHPULSE", "PAUSED_MOTION", "OHMIC_TEST", "PROBE_TEST",
    "SCRIBING", "CONSUMABLE_CHANGE_ON", "CONSUMABLE_CHANGE_OFF", "CUT_RECOVERY_ON", "CUT_RECOVERY_OFF",
    "DEBUG",
};

/* Counts moved toward target by at most v per call (LinuxCNC's offset move). */
static inline int pm_toward(int counts, int target, int v)
{
    if (counts - v > target) return counts - v;
    if (counts + v < target) return counts + v;
    return target;
}

/* A value held within lo..hi. */
static inline int pm_clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* A double as int counts, truncated and held within the int range (NaN gives 0). */
static inline int pm_counts(double v)
{
    if (v != v) return 0;
    if (v > 2147483647.0) return 2147483647;
    if (v < -2147483647.0) return -2147483647;
    return (int)v;
}

#endif
