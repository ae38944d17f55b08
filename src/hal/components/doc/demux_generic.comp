component demux_generic "Demultiplexers with a configurable size and input/output types";
modparam dummy config "Comma-separated demux specs: input type letter, output type letter, size 1..1024 (e.g. config=\"bf8,us4\"). Type letters: b bit, f float, s s32, u u32.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Demux NN (00, 01, ... in config order) copies its input, converted to the
output type, to output number S and sets every other output to 0. S = sel-int plus
the binary number on the sel-bit pins; when S is at or beyond the size all outputs
are 0. sel-bit pins exist when size/2 is a power of two (sizes 2, 3, 4, 5, 8, 9,
16, 17, ...); there are log2(size/2)+1 of them.

Pins of demux NN:
  demux-gen.NN.in-TYPE          TYPE in    the input
  demux-gen.NN.out-TYPE-MM      TYPE out   outputs, MM = 00 .. size-1
  demux-gen.NN.sel-bit-MM       bit in     binary selection bits
  demux-gen.NN.sel-int          u32 in     integer selection

Function demux-gen.NN (floating point) updates demux NN.""";
