component streamer "Drive HAL pins from a realtime stream fed by halstreamer";
modparam dummy cfg "Comma-separated channel configs, one type letter per pin: f or r float, b bit, s s32, u u32, l s64, k u64 (at most 21).";
modparam dummy depth "Comma-separated FIFO depths of the channels, in records.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Channel N (at most 8) has:
  streamer.N.pin.M        TYPE out  the driven pins
  streamer.N.enable       bit in    (default TRUE) read only while TRUE
  streamer.N.empty        bit out   the FIFO is empty
  streamer.N.curr-depth   s32 out   records waiting in the FIFO
  streamer.N.underruns    s32 io    calls that found the FIFO empty
  streamer.N.clock        bit in    clock input, see clock-mode
  streamer.N.clock-mode   s32 in    0 every call, 1 falling, 2 rising, 3 both edges of clock

Function streamer.N takes one record per (clocked) call from the stream of channel N;
when the FIFO is empty the pins keep their values.""";
see_also """halstreamer(1), sampler(9)""";
