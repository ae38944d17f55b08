component single "singleton";
pin out s32 calls;
option singleton yes;
function _;
license "GPL";
;;
calls = calls + 1;
