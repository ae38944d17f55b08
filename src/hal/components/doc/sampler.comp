component sampler "Sample HAL pins into a realtime stream read by halsampler";
modparam dummy cfg "Comma-separated channel configs, one type letter per pin: f or r float, b bit, s s32, u u32, l s64, k u64 (at most 21).";
modparam dummy depth "Comma-separated FIFO depths of the channels, in records (a depth-D stream holds D-1 records).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Channel N (at most 8) has:
  sampler.N.pin.M        TYPE in   the sampled pins
  sampler.N.enable       bit in    (default TRUE) sample only while TRUE
  sampler.N.full         bit out   the FIFO is full
  sampler.N.curr-depth   s32 out   records waiting in the FIFO
  sampler.N.overruns     s32 io    records lost because the FIFO was full
  sampler.N.sample-num   s32 io

Function sampler.N writes one record per call to the stream of channel N.""";
see_also """halsampler(1), streamer(9)""";
