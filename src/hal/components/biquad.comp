component biquad "Second-order IIR filter (biquad): direct coefficients, low-pass or notch";
pin in float in "Filter input";
pin out float out "Filter output (equal to in while disabled or invalid)";
pin in bit enable "Coefficients are computed on the rising edge; FALSE passes in through";
pin out bit valid "TRUE when the coefficients in use are valid";
pin in u32 type_ = 0 "0: use n0..d2 as given, 1: low-pass, 2: notch";
pin in float f0 = 250.0 "Corner or notch frequency in Hz";
pin in float Q = 0.7071 "Quality factor (0.5 to 2)";
pin out float s1 "First state variable";
pin out float s2 "Second state variable";
param rw float n0 = 1.0 "Numerator coefficient of x[n]";
param rw float n1 "Numerator coefficient of x[n-1]";
param rw float n2 "Numerator coefficient of x[n-2]";
param rw float d1 "Denominator coefficient of y[n-1]";
param rw float d2 "Denominator coefficient of y[n-2]";
variable int old_enable;
function _;
include <rtapi_math.h>;
license "GPL";
author "OpenEMC";
;;
int en = enable;
if (en && !old_enable) {
    double fs = 1.0 / fperiod, q = Q, w, c, a, a0;
    int t = type_;
    valid = 1;
    if (t == 1 || t == 2) {
        if (!(q >= 0.5 && q <= 2.0 && f0 > 0.0 && f0 <= fs / 2.0)) {  /* NaN fails too */
            valid = 0;
        } else {
            w = 2.0 * M_PI * f0 / fs;
            c = cos(w);
            a = sin(w) / (2.0 * q);
            a0 = 1.0 + a;
            n0 = (t == 1 ? (1.0 - c) / 2.0 : 1.0) / a0;
            n1 = (t == 1 ? 1.0 - c : -2.0 * c) / a0;
            n2 = n0;
            d1 = -2.0 * c / a0;
            d2 = (1.0 - a) / a0;
        }
    } else if (t != 0) {
        valid = 0;
    }
    s1 = 0;
    s2 = 0;
}
old_enable = en;
if (!en || !valid) {
    out = in;
} else {
    double x = in, y = n0 * x + s1;
    s1 = n1 * x - d1 * y + s2;
    s2 = n2 * x - d2 * y;
    out = y;
}
