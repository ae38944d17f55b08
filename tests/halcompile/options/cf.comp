component cf "count_function";
pin out s32 index;
variable int idx;
option count_function yes;
option extra_setup yes;
function _;
license "GPL";
;;
int get_count(void) { return 2; }
EXTRA_SETUP() { idx = (int)extra_arg; return 0; }
FUNCTION(_) { index = idx; }
