/* ml_format.h: motion-logger's text form of a motion command. */
#ifndef ML_FORMAT_H
#define ML_FORMAT_H

#include <stdio.h>
#include "motion_cmd.h"

/* Write one line for c (LinuxCNC motion-logger format). */
void ml_format(FILE *out, const emcmot_command_t *c);

#endif
