component logic "General logic function with up to 16 inputs";
pin in bit in-##[16 : personality & 0xff] "Inputs";
pin out bit and if personality & 0x100;
pin out bit or if personality & 0x200;
pin out bit xor if personality & 0x400;
pin out bit nand if personality & 0x800;
pin out bit nor if personality & 0x1000;
function _;
description "personality: low 8 bits = number of inputs, 0x100 and, 0x200 or, 0x400 xor, 0x800 nand, 0x1000 nor.";
license "GPL";
;;
int i, n = personality & 0xff, all = 1, any = 0, ones = 0;
for (i = 0; i < n; i++) {
    if (in(i)) { any = 1; ones++; } else all = 0;
}
if (personality & 0x100) and = all;
if (personality & 0x200) or = any;
if (personality & 0x400) xor = ones & 1;
if (personality & 0x800) nand = !all;
if (personality & 0x1000) nor = !any;
