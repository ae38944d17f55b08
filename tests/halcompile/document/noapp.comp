component noapp "a module that sets up its own instances";
modparam dummy cfg "instance list";
pin out bit q;
option rtapi_app no;
function _;
license "GPL";
;;
FUNCTION(_) { q = 1; }
