#!/bin/bash
# the tool-data segment: publish, read, find, put, generations, creator removes it
"$EMC2_HOME/objects/unit/nml_test" tooldata
