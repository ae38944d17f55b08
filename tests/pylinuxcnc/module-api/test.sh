#!/bin/bash
# The linuxcnc module without a running machine: attributes, constants, types, argument
# checks and their error texts, and the not-running behaviour of every channel object.
python3 -u "$(dirname "$0")/api.py" 2>&1
