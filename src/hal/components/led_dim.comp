component led_dim "Perceived brightness to LED luminance (CIE 1931 lightness)";
pin in float in "Brightness 0..1";
pin out float out "Luminance 0..1";
variable double last;
function _;
license "GPL";
author "OpenEMC";
;;
(void)period;
if (in != last) {
    double x = in;
    last = in;
    if (!(x > 0)) x = 0;  /* also NaN */
    if (x > 1) x = 1;
    out = x < 0.079996 ? x / 9.033 : ((x + 0.16) / 1.16) * ((x + 0.16) / 1.16) * ((x + 0.16) / 1.16);
}
