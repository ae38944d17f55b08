component crlf "CRLF line endings";
pin out s32 out;
function _;
license "GPL";
;;
out = 3;
