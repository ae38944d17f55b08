/* genser_urdf_missing.c: genser_urdf_load for builds without urdfdom: refuses with the reason. */
#include <errno.h>
#include <stdio.h>
#include "genser_urdf.h"

/* No URDF reader in this build: name the file and say why it cannot be read. */
int genser_urdf_load(const char *path, double scale, genser_chain_t *chain, char *why,
                     size_t why_size)
{
    (void)scale;
    (void)chain;
    snprintf(why, why_size, "urdf '%s': this build has no URDF support (urdfdom was not found)",
             path);
    return -ENOSYS;
}
