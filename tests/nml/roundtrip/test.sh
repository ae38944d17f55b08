#!/bin/bash
# every message type through a shm queue in one process and between two; the codec table
"$EMC2_HOME/objects/unit/nml_test" roundtrip roundtrip-fork codec
