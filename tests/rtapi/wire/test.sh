#!/bin/bash
# rtapi_app protocol: round trips and rejection of every malformed length field.
"$EMC2_HOME/objects/unit/rtapi_wire_test"
