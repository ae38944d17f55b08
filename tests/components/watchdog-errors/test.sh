#!/bin/bash
# watchdog needs num_inputs between 1 and 32.
for a in "" num_inputs=33; do echo "== $a"; echo "load watchdog $a" | "$EMC2_HOME/objects/unit/comptest"; done
