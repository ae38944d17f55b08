/* ml_state.h: the status motion-logger publishes, updated from the commands it logs. */
#ifndef ML_STATE_H
#define ML_STATE_H

#include "motion_status.h"

/* Start: one spindle, three joints, disabled, everything at rest. */
void ml_state_init(emcmot_status_t *st);
/* What a real motion controller would show after accepting c (moves complete at once). */
void ml_state_apply(emcmot_status_t *st, const emcmot_command_t *c);

#endif
