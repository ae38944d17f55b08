component bin2gray "Convert a binary number to Gray code";
pin in u32 in "Binary value";
pin out u32 out "Gray code of in";
function _;
license "GPL";
author "OpenEMC";
;;
out = in ^ (in >> 1);
