#!/bin/bash
# Canned cycles in G18/G19/G17.1, G84/G74 tapping (with the reference's XZ/YZ feed order), G87/G88, G7.
cd "$(dirname "$0")"
"$EMC2_HOME/objects/unit/cycles_unit" < cases.txt
