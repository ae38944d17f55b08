#!/bin/bash
# A subroutine file on SUBROUTINE_PATH is kept between calls but read again after it changes on disk.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$EMC2_HOME/objects/unit/sub_reload_unit" "$work" | sed -e 's/^ *[0-9]* N/N/'
exit "${PIPESTATUS[0]}"
