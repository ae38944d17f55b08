#!/bin/bash
# Start-up of the embedded Python: a missing or broken TOPLEVEL stops rs274 with the file and the Python
# error; bad REMAP= lines and remap functions that do not exist are reported with file:line.
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
clean() { sed -e 's/^ *[0-9]* N/N/' -e "s|$PWD/||g"; }
echo "== missing TOPLEVEL"; rs274 -i missing.ini -g m430.ngc 2>&1 | clean; echo "exit ${PIPESTATUS[0]}"
echo "== broken TOPLEVEL"; rs274 -i broken.ini -g m430.ngc 2>&1 | clean; echo "exit ${PIPESTATUS[0]}"
echo "== bad REMAP lines"; rs274 -i noremap.ini -g m430.ngc 2>&1 | clean; echo "exit ${PIPESTATUS[0]}"
echo "== no [PYTHON]"; rs274 -g nopython.ngc 2>&1 | clean; echo "exit ${PIPESTATUS[0]}"
