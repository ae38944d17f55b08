component demux_generic "Demultiplexers with a configurable size and input/output types";
modparam dummy config "Comma-separated demux specs: type letters and size in any order (e.g. config=\"bf8,us4\"). Type letters: b bit, f float, s s32, u u32.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each config string holds the size (digits) and one or two type letters, in any order
(bb8, 8bb, b8f, b2b, f5f); one letter means the output has the input type. Sizes
above 1024 become 1024; size 0 or 1, a third letter or another character fail the load.

Demux NN (00, 01, ... in config order) copies its input, converted to the
output type, to output number S and sets every other output to 0. S = sel-int plus
the binary number on the sel-bit pins; when S is at or beyond the size all outputs
are 0. sel-bit pins exist when size/2 is a power of two (sizes 2, 3, 4, 5, 8, 9,
16, 17, ...); there are log2(size/2)+1 of them.

Pins of demux NN:
  demux-gen.NN.in-TYPE          TYPE in    the input
  demux-gen.NN.out-TYPE-MM      TYPE out   outputs, MM = 00 .. size-1
  demux-gen.NN.sel-bit-MM       bit in     binary selection bits
  demux-gen.NN.sel-int          u32 in     integer selection
  demux-gen.NN.suppress-no-input bit in    when TRUE, selection 0 leaves the outputs unchanged
  demux-gen.NN.debounce-us      u32 in     a new selection waits this long (us) before it is used

Parameters of demux NN:
  demux-gen.NN.elapsed    u32 r   time a new selection has been waiting (us)
  demux-gen.NN.selected   u32 r   the selection in use

Function demux-gen.NN (floating point) updates demux NN.""";
