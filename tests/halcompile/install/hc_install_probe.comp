component hc_install_probe "A user's own component installed with halcompile --install";
pin in float in;
pin out float out "in + offset";
param rw float offset = 0.5;
function _;
license "GPL";
;;
out = in + offset;
