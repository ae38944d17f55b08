#!/bin/bash
# matrixkins through the fake-HAL harness: C_xx..C_zz params, identity default, skewed matrix both ways, singular matrix refused.
exec "$EMC2_HOME/objects/unit/comptest" < script
