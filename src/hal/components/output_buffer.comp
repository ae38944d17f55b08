component output_buffer "Pass up to 32 bits through while enabled, else drive them to an off level";
description "personality is the number of channels (at most 32; the default 0 makes none).";
pin in bit enable "Pass the inputs through";
pin in bit off_level "Level of every output while disabled";
pin in bit in-#[32 : personality] "Input i";
pin out bit out-#[32 : personality] "Output i";
function _;
license "GPL";
author "OpenEMC";
;;
(void)period;
for (int i = 0; i < personality && i < 32; i++)
    out(i) = enable ? in(i) : off_level;
