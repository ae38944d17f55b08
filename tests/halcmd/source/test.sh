#!/bin/bash
# source: nested files, messages naming the sourced file, stop at the first error, no continuation.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
halcmd -f main.hal 2>&1
echo "exit $?"
halcmd source nosuch.hal 2>&1
echo "exit $?"
halcmd -k -f main.hal 2>&1
echo "exit $?"
echo "> self-sourcing file"
halcmd -f loop.hal 2>&1 | tail -1
echo "exit ${PIPESTATUS[0]}"
realtime stop
