/* genser_urdf.h: read a genserkins chain from a URDF robot description (at load time only). */
#ifndef GENSER_URDF_H
#define GENSER_URDF_H

#include <stddef.h>
#include "genser_math.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Read the single chain of path: exactly GENSER_JOINTS revolute/continuous joints, fixed joints
 * folded into their neighbours, lengths multiplied by scale (machine units per URDF metre).
 * 0, or a negative errno with why naming the file and what is wrong. */
int genser_urdf_load(const char *path, double scale, genser_chain_t *chain, char *why,
                     size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
