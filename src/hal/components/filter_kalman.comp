component filter_kalman "One-dimensional Kalman filter (constant-state model) for noisy measurements";
description """
Each call predicts P = P + Qk, then updates with the measurement zk:
K = P/(Rk + P), x = x + K(zk - x), P = (1 - K)P.  \\fBreset\\fR sets x = 0, P = 1;
\\fBpassthrough\\fR copies zk to the output without touching the filter.
""";
pin in bit debug "Print index, zk and xk-out every call";
pin in bit passthrough "Copy zk to xk-out";
pin in bit reset "Restart the filter (x = 0, P = 1)";
pin in float zk "Measurement";
pin out float xk_out "Estimate";
param rw float Rk = 1.17549e-38 "Measurement noise covariance";
param rw float Qk = 1.17549e-38 "Process noise covariance";
variable double xk;
variable double pk;
variable int ready;
variable int index;
option extra_setup yes;
function _;
license "GPL";
author "OpenEMC";
;;
/* Remember the 0-based instance number for the debug line. */
EXTRA_SETUP()
{
    (void)prefix;
    index = extra_arg;
    return 0;
}

FUNCTION(_)
{
    (void)period;
    if (reset || !ready) {
        xk = 0;
        pk = 1;
        ready = 1;
    }
    if (reset) {
        xk_out = 0;
    } else if (passthrough) {
        xk_out = zk;
    } else {
        double p = pk + Qk, k = p / (Rk + p);
        xk += k * (zk - xk);
        pk = (1 - k) * p;
        xk_out = xk;
    }
    if (debug)
        rtapi_print_msg(RTAPI_MSG_ERR, "filter-kalman.%d %f %f\n", index, zk, xk_out);
}
