#!/bin/bash
# Remapped T, M6, S and M61 with Python glue written like stdglue: prologs read the block, NGC procedures
# see the injected parameters, epilogs emit the canon calls, load the tool (set_tool_parameters) and set the
# speed through self.speed; #5400-#5413 and #<_rpm> follow.
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
rs274 -i test.ini -t test.tbl -n 0 -g test.ngc 2>&1 | sed -e 's/^ *[0-9]* N/N/' -e "s|$PWD/||"
exit "${PIPESTATUS[0]}"
