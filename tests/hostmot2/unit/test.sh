#!/bin/bash
# unit: config strings, LBP16 words, encoder/PWM/stepgen arithmetic, bitfiles and names, without HAL.
"$EMC2_HOME/objects/unit/hm2_unit"
