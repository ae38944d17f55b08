/* cia402_state.h: the CiA 402 drive state machine seen from the master (statusword -> state, controlword). */
#ifndef CIA402_STATE_H
#define CIA402_STATE_H

#include <stdint.h>

/* Drive states (also the value of the cia402.N.state pin). */
typedef enum {
    CIA402_NOT_READY = 0,
    CIA402_SWITCH_ON_DISABLED = 1,
    CIA402_READY_TO_SWITCH_ON = 2,
    CIA402_SWITCHED_ON = 3,
    CIA402_OPERATION_ENABLED = 4,
    CIA402_QUICK_STOP_ACTIVE = 5,
    CIA402_FAULT_REACTION_ACTIVE = 6,
    CIA402_FAULT = 7,
    CIA402_UNKNOWN = 8
} cia402_state_t;

/* Controlword commands. */
#define CIA402_CW_DISABLE_VOLTAGE 0x0000u
#define CIA402_CW_SHUTDOWN 0x0006u
#define CIA402_CW_SWITCH_ON 0x0007u
#define CIA402_CW_DISABLE_OPERATION 0x0007u
#define CIA402_CW_ENABLE_OPERATION 0x000Fu
#define CIA402_CW_FAULT_RESET 0x0080u

/* Statusword bits used outside the state decoding. */
#define CIA402_SW_FAULT 0x0008u
#define CIA402_SW_WARNING 0x0080u

/* The state a statusword reports. */
cia402_state_t cia402_decode(uint16_t statusword);

/* The state's name as CiA 402 spells it. */
const char *cia402_state_name(cia402_state_t state);

/* The controlword that moves a drive in state one step toward Operation Enabled. */
uint16_t cia402_enable_step(cia402_state_t state);

#endif
