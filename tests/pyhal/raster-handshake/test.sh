#!/bin/bash
# raster-handshake: RasterProgrammer.start()/stop() wait for the raster component's answer.
. ../lib.sh
pyhal_run handshake.py setup.hal
