#!/bin/bash
# a full queue refuses the write and keeps order; wrap-around FIFO; a ring read to its very end; confirm_write
"$EMC2_HOME/objects/unit/nml_test" queue-full queue-wrap queue-end confirm-write
