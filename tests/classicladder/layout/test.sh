#!/bin/bash
# layout: the loader's check of a data-segment header read from shared memory.
exec "$EMC2_HOME/objects/unit/cl_layout_test"
