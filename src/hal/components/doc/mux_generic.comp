component mux_generic "Multiplexers with a configurable size and input/output types";
modparam dummy config "Comma-separated mux specs: input type letter, output type letter, size 1..1024 (e.g. config=\"bb8,fu12\"). Type letters: b bit, f float, s s32, u u32.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Mux NN (00, 01, ... in config order) copies input number S to its output,
converting the value to the output type. S = sel-int plus the binary number on the
sel-bit pins. sel-bit pins exist when size/2 is a power of two (sizes 2, 3, 4, 5,
8, 9, 16, 17, ...); there are log2(size/2)+1 of them.

Pins of mux NN:
  mux-gen.NN.in-TYPE-MM          TYPE in    inputs, MM = 00 .. size-1
  mux-gen.NN.out-TYPE            TYPE out   the selected input
  mux-gen.NN.sel-bit-MM          bit in     binary selection bits
  mux-gen.NN.sel-int             u32 in     integer selection
  mux-gen.NN.suppress-no-input   bit in     when TRUE, selection 0 leaves the output unchanged
  mux-gen.NN.debounce-us         u32 in     the selection must be stable this long (us)

Parameters of mux NN:
  mux-gen.NN.elapsed    u32 r   time the current selection has been stable (us)
  mux-gen.NN.selected   u32 r   the selection in use

A selection at or beyond the size leaves the output unchanged.

Function mux-gen.NN (floating point) updates mux NN.""";
