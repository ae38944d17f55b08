#!/bin/bash
# Introspection from Python (params.locals/globals, sub_context, blocks, tool_table, active_g_codes) and
# #<_name> parameters defined by functions of module namedparams (read-only, errors reported).
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
rs274 -i test.ini -t test.tbl -n 0 -g test.ngc 2>&1 | sed -e 's/^ *[0-9]* N/N/' -e "s|$PWD/||"
exit "${PIPESTATUS[0]}"
