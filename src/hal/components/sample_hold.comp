component sample_hold "Sample and hold an s32 value";
pin in s32 in;
pin in bit hold "When TRUE, out keeps its value";
pin out s32 out;
function _;
license "GPL";
author "OpenEMC";
;;
if (!hold) out = in;
