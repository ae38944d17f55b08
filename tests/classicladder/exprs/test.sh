#!/bin/bash
# Expression operators, functions and precedence; IEC timers TOF and TP; vertical OR links.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cl_sim" < script
