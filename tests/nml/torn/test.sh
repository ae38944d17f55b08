#!/bin/bash
# a reader hammering the status buffer under a 1 kHz writer never sees a torn snapshot
"$EMC2_HOME/objects/unit/nml_test" torn
