#!/bin/bash
# ports: byte FIFOs between PORT pins of a Python component.
. ../lib.sh
pyhal_run ports.py
