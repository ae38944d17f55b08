#!/bin/bash
# Unit test of linuxcncrsh's text helpers.
"$EMC2_HOME/objects/unit/rsh_format_test"
