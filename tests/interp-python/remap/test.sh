#!/bin/bash
# Remaps with Python: prolog variables seen by the NGC body and read back by the epilog, python= bodies with
# their words, errors (returned text, set_errormsg + INTERP_ERROR, exceptions) echoing the O-call line,
# yield INTERP_EXECUTE_FINISH, an epilog keeping a remapped G code modal, and self.execute().
export PYTHONUNBUFFERED=1 PYTHONDONTWRITEBYTECODE=1
rs274 -i test.ini -n 0 -g test.ngc 2>&1 | sed -e 's/^ *[0-9]* N/N/' -e "s|$PWD/||"
exit "${PIPESTATUS[0]}"
