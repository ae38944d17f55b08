#!/bin/bash
# unit: config strings, LBP16 words, encoder/PWM/stepgen arithmetic, bitfiles and names, Smart Serial
# process-data packing, without HAL.
"$EMC2_HOME/objects/unit/hm2_unit"
"$EMC2_HOME/objects/unit/sserial_unit"
