#!/bin/bash
# ctypes: the pyhal module (ctypes over liblinuxcnchal) and the raster module built on it.
. ../lib.sh
pyhal_run ctypes_pyhal.py
