#!/bin/bash
# one serial sequence for all writers, in one process and across processes
"$EMC2_HOME/objects/unit/nml_test" serial-shared serial-fork
