component supply "Set output pins from parameter values";
modparam dummy num_chan "Number of supplies, 1 to 8 (default 1).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each channel N copies its two parameters to its outputs, the underscore pins
inverted. The parameters are set with setp (they cannot be linked to signals).

Parameters of channel N:
  supply.N.d        bit rw     data value (default FALSE)
  supply.N.value    float rw   analog value (default 0.0)

Pins of channel N:
  supply.N.q        bit out    = d
  supply.N._q       bit out    = not d
  supply.N.variable float out  = value
  supply.N._variable float out = -value

Function supply.N.update (floating point) updates channel N.""";
