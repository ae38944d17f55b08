#!/bin/bash
# pentakins through the fake-HAL harness: geometry and solver pins, home pose both ways, iteration pins, solver limits.
exec "$EMC2_HOME/objects/unit/comptest" < script
