#!/bin/bash
# corrupt messages (unknown type, wrong size, unterminated text) refused by readers and writers
"$EMC2_HOME/objects/unit/nml_test" corrupt
