component inc "include of a header next to the .comp, modparam dummy";
pin out s32 out;
include "inc_value.h";
modparam dummy extra "declared by the C code";
function _;
license "GPL";
;;
static int extra = 0;
RTAPI_MP_INT(extra, "an extra value");
FUNCTION(_) { out = INC_VALUE + extra; }
