#!/bin/bash
# futex waits across processes, timeouts, a master leaving
"$EMC2_HOME/objects/unit/nml_test" wait shutdown
