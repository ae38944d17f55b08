#!/bin/bash
# Unit test of halui's override knob logic.
"$EMC2_HOME/objects/unit/halui_override_test"
