#!/bin/bash
# component-link: Python hal component <-> halcmd, values both ways.
. ../lib.sh
pyhal_run pycomp.py
