component sphereprobe "Probe a pretend hemisphere";
pin in s32 px "Probe X position in raw counts";
pin in s32 py "Probe Y position in raw counts";
pin in s32 pz "Probe Z position in raw counts";
pin in s32 cx "X of the centre of the sphere in counts";
pin in s32 cy "Y of the centre of the sphere in counts";
pin in s32 cz "Z of the centre of the sphere in counts";
pin in s32 r "Radius of the hemisphere in counts";
pin out bit probe_out "TRUE while the probe touches the hemisphere or the plane it rests on";
function _ "Update probe-out from the inputs";
description """LinuxCNC's sphereprobe: the hemisphere of radius r around (cx, cy, cz) rests on a
plane at cz. With dx, dy, dz the distances of the probe from the centre (32-bit differences,
which wrap like LinuxCNC's, then taken as magnitudes): outside the footprint circle
(dx^2 + dy^2 > r^2) the probe trips below the plane (pz < cz); inside it the probe trips
within the sphere (dx^2 + dy^2 + dz^2 <= r^2). The squares are exact unsigned 64-bit
arithmetic.""";
license "GPL";
author "OpenEMC";
;;
#include <stdint.h>

/* |a - b| with the difference wrapped to 32 bits, as an unsigned 64-bit magnitude. */
static uint64_t sp_dist(hal_s32_t a, hal_s32_t b)
{
    int32_t d = (int32_t)((uint32_t)a - (uint32_t)b);
    return d < 0 ? (uint64_t)(-(int64_t)d) : (uint64_t)d;
}

FUNCTION(_)
{
    uint64_t dx = sp_dist(px, cx), dy = sp_dist(py, cy), dz = sp_dist(pz, cz);
    uint64_t d2 = dx * dx + dy * dy, r2 = (uint64_t)((int64_t)r * r);
    if (d2 > r2) probe_out = pz < cz;
    else probe_out = d2 + dz * dz <= r2;
}
