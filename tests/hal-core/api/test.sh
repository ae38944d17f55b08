#!/bin/bash
# HAL library user-side API: comps/ids, pins, params, link rules, ports, aliases, locks, streams (stderr included).
"$EMC2_HOME/objects/unit/hal_core_api" 2>&1
