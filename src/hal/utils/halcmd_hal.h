/* halcmd_hal.h: halcmd's own HAL attachment, fork id cost and component helpers. */
#ifndef HALCMD_HAL_H
#define HALCMD_HAL_H

#include "hal_priv.h"

#define HC_COMP_TYPE_RT HAL_COMP_RT
#define HC_COMP_TYPE_USER HAL_COMP_USER

int hc_hal_attach(void);
void hc_hal_detach(void);
void hc_hal_fork_cost(void);
int hc_hal_release_mutex(void);
void hc_hal_set_insmod_args(const char *comp, const char *args);
void hc_hal_comp_names(int type, char ***names, int *count);
int hc_complete_bash(void);
const char *hc_bindir(void);

#endif
