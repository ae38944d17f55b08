#!/bin/bash
# stream: Python access to HAL streams, alone and through streamer/sampler.
. ../lib.sh
pyhal_run streams.py setup.hal
