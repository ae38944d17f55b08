/* cia402_state.c: decode the CiA 402 statusword and pick the controlword toward Operation Enabled. */
#include "cia402_state.h"

/* Statusword patterns: (statusword & mask) == value. */
static const struct {
    uint16_t mask, value;
    cia402_state_t state;
} patterns[] = {
    { 0x4F, 0x00, CIA402_NOT_READY },
    { 0x4F, 0x40, CIA402_SWITCH_ON_DISABLED },
    { 0x6F, 0x21, CIA402_READY_TO_SWITCH_ON },
    { 0x6F, 0x23, CIA402_SWITCHED_ON },
    { 0x6F, 0x27, CIA402_OPERATION_ENABLED },
    { 0x6F, 0x07, CIA402_QUICK_STOP_ACTIVE },
    { 0x4F, 0x0F, CIA402_FAULT_REACTION_ACTIVE },
    { 0x4F, 0x08, CIA402_FAULT },
};

static const char *const names[] = {
    "Not ready to switch on", "Switch on disabled", "Ready to switch on", "Switched on",
    "Operation enabled", "Quick stop active", "Fault reaction active", "Fault", "unknown",
};

/* The state a statusword reports. */
cia402_state_t cia402_decode(uint16_t statusword)
{
    for (unsigned i = 0; i < sizeof(patterns) / sizeof(patterns[0]); i++)
        if ((statusword & patterns[i].mask) == patterns[i].value)
            return patterns[i].state;
    return CIA402_UNKNOWN;
}

/* The state's name as CiA 402 spells it. */
const char *cia402_state_name(cia402_state_t state)
{
    return names[state <= CIA402_UNKNOWN ? state : CIA402_UNKNOWN];
}

/* The controlword that moves a drive in state one step toward Operation Enabled. */
uint16_t cia402_enable_step(cia402_state_t state)
{
    switch (state) {
    case CIA402_SWITCH_ON_DISABLED: return CIA402_CW_SHUTDOWN;
    case CIA402_READY_TO_SWITCH_ON: return CIA402_CW_SWITCH_ON;
    case CIA402_SWITCHED_ON:
    case CIA402_OPERATION_ENABLED: return CIA402_CW_ENABLE_OPERATION;
    default: return CIA402_CW_DISABLE_VOLTAGE;
    }
}
