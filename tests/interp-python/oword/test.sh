#!/bin/bash
# Python O-word subroutines (module oword): arguments, return values as #<_value>, their own call level,
# a returned string as an error, exceptions reported with file, line and type; ;py, lines; __init__/__delete__.
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
rs274 -i test.ini -n 0 -g test.ngc 2>&1 | sed -e 's/^ *[0-9]* N/N/' -e "s|$PWD/||"
exit "${PIPESTATUS[0]}"
