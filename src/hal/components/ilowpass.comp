component ilowpass "Low-pass filter with integer input and output";
pin in s32 in;
pin out s32 out "floor(value * scale + 0.5) as a 64-bit integer, keeping its low 32 bits (wraps like LinuxCNC)";
param rw float scale = 1024 "Output scale";
param rw float gain = 0.5 "Filter gain";
variable double value;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
value += (in - value) * gain;
double o = floor(value * scale + 0.5);
long long wide;
if (o != o)
    wide = 0;  /* NaN gain or scale: report 0 */
else if (o >= 9223372036854775807.0)
    wide = 9223372036854775807LL;  /* beyond 64 bits: saturate, then wrap like any other value */
else if (o <= -9223372036854775808.0)
    wide = -9223372036854775807LL - 1;
else
    wide = (long long)o;
out = (hal_s32_t)(hal_u32_t)(unsigned long long)wide;
