component bitmerge "Combine bits into a u32 (the inverse of bitslice)";
description "personality is the number of inputs (at most 32; the default 0 makes none and out stays 0).";
pin in bit in-##[32 : personality] "Bit NN of out";
pin out u32 out "Sum of in-NN x 2^NN";
function _;
license "GPL";
author "OpenEMC";
;;
hal_u32_t v = 0;
(void)period;
for (int i = 0; i < personality && i < 32; i++)
    if (in(i))
        v |= 1u << i;
out = v;
