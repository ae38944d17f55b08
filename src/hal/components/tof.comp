component tof "IEC off-delay timer";
pin in bit in;
pin out bit q "TRUE while in is TRUE and for pt seconds after it falls";
pin out float et "Elapsed time since in fell, in seconds";
param rw float pt "Preset time in seconds";
function _;
license "GPL";
author "OpenEMC";
;;
if (in) {
    et = 0;
    q = 1;
} else if (q) {
    double e = et + fperiod;
    if (e >= pt) {
        e = pt;
        q = 0;
    }
    et = e;
}
