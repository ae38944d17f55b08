#!/bin/bash
# Cutter comp geometry errors: short entry, arc after G40, tool too big for an inside arc, concave gouges.
. "$TEST_DIR/../../interp-cycles/ngc_errors.sh"
report_ngc_errors test.tbl
