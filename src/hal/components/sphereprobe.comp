component sphereprobe "Probe a pretend hemisphere";
pin in s32 px "Probe X position in raw counts";
pin in s32 py "Probe Y position in raw counts";
pin in s32 pz "Probe Z position in raw counts";
pin in s32 cx "X of the centre of the sphere in counts";
pin in s32 cy "Y of the centre of the sphere in counts";
pin in s32 cz "Z of the centre of the sphere in counts";
pin in s32 r "Radius of the hemisphere in counts";
pin out bit probe_out "TRUE while the probe point is inside or on the hemisphere";
function _ "Update probe-out from the inputs";
description """The hemisphere is the upper half (z >= cz) of the sphere of radius r around
(cx, cy, cz), sitting on a solid base: a point whose horizontal distance from the
centre is at most r trips the probe when it is below cz or inside the dome. A point
farther out never trips it. Arithmetic is exact 64-bit integer arithmetic.""";
license "GPL";
author "OpenEMC";
;;
long long dx = (long long)px - cx, dy = (long long)py - cy, dz = (long long)pz - cz;
long long rr = (long long)r * r;
if (r < 0 || dx > r || dx < -(long long)r || dy > r || dy < -(long long)r) {
    probe_out = 0;
    return;
}
rr -= dx * dx + dy * dy;
probe_out = rr >= 0 && (dz < 0 || (dz <= r && dz * dz <= rr));
