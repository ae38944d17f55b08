component supply "Set output pins from input values";
modparam dummy num_chan "Number of supplies, 1 to 8 (default 1).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each channel N copies its inputs to its outputs, the underscore pins inverted.

Pins of channel N:
  supply.N.d        bit in     data input
  supply.N.value    float in   value input
  supply.N.q        bit out    = d
  supply.N._q       bit out    = not d
  supply.N.variable float out  = value
  supply.N._variable float out = -value

Function supply.N.update (floating point) updates channel N.""";
