#!/bin/bash
# Canned-cycle and G76 error paths: each program must stop with exit 1 and the exact error text.
. "$TEST_DIR/../ngc_errors.sh"
report_ngc_errors test.tbl
