component scaled_s32_sums "Sum of four scaled s32 inputs";
pin in s32 input#[4] "Inputs";
pin in float scale#[4] = 1.0 "Scale of each input";
pin out s32 output "Sum of input-i * scale-i, truncated";
function _;
license "GPL";
author "OpenEMC";
;;
int i;
double s = 0;
for (i = 0; i < 4; i++) s += input(i) * scale(i);
if (s != s) s = 0.0;  /* NaN scale: 0 */
output = s >= 2147483647.0 ? 2147483647 : s <= -2147483648.0 ? (-2147483647 - 1) : (hal_s32_t)s;
