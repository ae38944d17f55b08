#!/bin/bash
# canon calls -> NML messages (units, limits along the path, naive-CAM merging, arcs, offsets),
# NML -> EMCMOT translation and tool table files, without a machine
"$EMC2_HOME/objects/unit/task_canon_test"
