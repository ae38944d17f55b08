component ilowpass "Low-pass filter with integer input and output";
pin in s32 in;
pin out s32 out "floor(value * scale + 0.5)";
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
if (o != o) o = 0.0;  /* NaN gain or scale: report 0 */
out = o >= 2147483647.0 ? 2147483647 : o <= -2147483648.0 ? (-2147483647 - 1) : (hal_s32_t)o;
