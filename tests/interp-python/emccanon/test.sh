#!/bin/bash
# The emccanon module: canon calls of every argument shape and GET_EXTERNAL_* queries from a Python remap
# reach the canon in order (rs274 prints them); wrong arguments raise TypeError.
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
rs274 -i test.ini -g test.ngc 2>&1 | sed -e 's/^ *[0-9]* N/N/'
exit "${PIPESTATUS[0]}"
