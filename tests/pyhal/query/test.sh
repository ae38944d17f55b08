#!/bin/bash
# query: hal.query dictionaries for a small HAL configuration.
. ../lib.sh
pyhal_run query.py setup.hal
