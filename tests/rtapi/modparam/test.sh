#!/bin/bash
# Module parameter parsing: every type, arrays, quotes and malformed values.
"$EMC2_HOME/objects/unit/rtapi_modparam_test"
