component pp "personality wrap with -P";
pin out s32 p;
pin out bit flag if personality > 1;
function _;
license "GPL";
;;
p = personality;
