component enum "Decode an integer into one bit per named value, or encode such bits";
modparam dummy enums "Comma-separated channel specs: D (decode) or E (encode), then the value labels, each preceded by ';'. An empty label skips that value. Example: enums=D;off;on;;max,E;;red;green";
modparam dummy names "Optional channel names, one per spec (default enum.N).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Value labels are numbered from 0 in the order given (empty labels count),
and the number of each value can be changed through its -val pin.

Pins of a decode channel P:
  P.input        u32 in    the number to decode
  P.LABEL-out    bit out   TRUE while input equals LABEL-val
  P.LABEL-val    u32 in    the number of LABEL (default: its position)

Pins of an encode channel P:
  P.LABEL-in     bit in    request value LABEL
  P.LABEL-val    u32 in    the number of LABEL (default: its position)
  P.output       u32 out   LABEL-val of the first listed LABEL-in that is TRUE, else 0

Functions: P.decode or P.encode (no floating point), one per channel.

A spec that does not start with D; or E;, names no value, or has more than 64
values or a label longer than 40 characters is rejected.""";
