component lut5 "Arbitrary logic function of up to five bits, given as a truth table";
pin in bit in-#[5] "Logic inputs; in-N has weight 2^N in the table index";
pin out bit out "Truth-table entry selected by the current inputs";
param rw u32 function "Truth table: bit K is the output when the inputs, read as a binary number, equal K";
function _ "Look up the output for the current inputs";
license "GPL";
author "OpenEMC";
description """
The five inputs form an index from 0 to 31 (in-0 is the least significant
bit).  The output is bit number index of the function parameter.  Unused
inputs stay FALSE, so a two-input function only needs bits 0 to 3.
Examples of function values: AND of in-0 and in-1 is 0x8, OR of in-0 and in-1
is 0xe, XOR of in-0 and in-1 is 0x6, AND of all five inputs is 0x80000000,
OR of all five inputs is 0xfffffffe.
""";
;;
unsigned index = 0;
int i;
for (i = 0; i < 5; i++)
    if (in(i)) index |= 1u << i;
out = (function >> index) & 1u;
