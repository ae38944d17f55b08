component mux_generic "Multiplexers with a configurable size and input/output types";
modparam dummy config "Comma-separated mux specs: type letters and size in any order (e.g. config=\"bb8,fu12\"). Type letters: b bit, f float, s s32, u u32.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each config string holds the size (digits) and one or two type letters, in any order
(bb8, 8bb, b8f, b2b, f5f); one letter means the output has the input type. Sizes
above 1024 become 1024; size 0 or 1, a third letter or another character fail the load.

Mux NN (00, 01, ... in config order) copies input number S to its output,
converting the value to the output type. S = sel-int plus the binary number on the
sel-bit pins. sel-bit pins exist when size/2 is a power of two (sizes 2, 3, 4, 5,
8, 9, 16, 17, ...); there are log2(size/2)+1 of them.

Pins of mux NN:
  mux-gen.NN.in-TYPE-MM          TYPE in    inputs, MM = 00 .. size-1
  mux-gen.NN.out-TYPE            TYPE out   the selected input
  mux-gen.NN.sel-bit-MM          bit in     binary selection bits
  mux-gen.NN.sel-int             u32 in     integer selection
  mux-gen.NN.suppress-no-input   bit in     when TRUE, selection 0 leaves the output unchanged
  mux-gen.NN.debounce-us         u32 in     a new selection waits this long (us) before it is used

Parameters of mux NN:
  mux-gen.NN.elapsed    u32 r   time a new selection has been waiting (us)
  mux-gen.NN.selected   u32 r   the selection in use

A selection at or beyond the size uses the last input. Conversions: float to s32/u32
truncates and clamps to the target range (NaN gives 0), s32 to u32 gives 0 for negative
values, u32 to s32 clamps at 2147483647, float to bit is TRUE when |value| > 2e-7.

Function mux-gen.NN (floating point) updates mux NN.""";
