component ton "IEC on-delay timer";
pin in bit in;
pin out bit q "TRUE once in has been TRUE for pt seconds";
pin out float et "Elapsed time in seconds";
param rw float pt "Preset time in seconds";
function _;
license "GPL";
author "OpenEMC";
;;
if (in) {
    double e = et;
    if (e < pt) e += fperiod;
    if (e >= pt) {
        e = pt;
        q = 1;
    }
    et = e;
} else {
    et = 0;
    q = 0;
}
