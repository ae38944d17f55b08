component supply "Set output pins from the d and value pins";
modparam dummy num_chan "Number of supplies, 1 to 8 (default 1).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Each channel N copies its d and value pins to its outputs, the underscore pins
inverted. d and value are I/O pins: set them with setp or drive them from a signal.

Pins of channel N:
  supply.N.d         bit io     data value (default FALSE)
  supply.N.value     float io   analog value (default 0.0)
  supply.N.q         bit out    = d
  supply.N._q        bit out    = not d (TRUE at load)
  supply.N.variable  float out  = value
  supply.N._variable float out  = -value

Function supply.N.update (floating point) updates channel N.""";
