#!/bin/bash
# #<_hal[name]> asks the installed reader (unknown names are not defined, EXISTS 0); M1nn calls the handler.
# Then the M1nn search: PROGRAM_PREFIX first, then each USER_M_PATH dir; only executable files count.
"$EMC2_HOME/objects/unit/interp_hooks_unit"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/prefix" "$work/user1" "$work/user2"
printf '#!/bin/sh\n' | tee "$work/prefix/M101" "$work/user1/M101" "$work/user2/M102" \
    "$work/user1/M103" "$work/user2/M103" > /dev/null
chmod +x "$work/prefix/M101" "$work/user1/M101" "$work/user2/M102" "$work/user2/M103"
mkdir "$work/user1/M104"
printf '[DISPLAY]\nPROGRAM_PREFIX = %s/prefix\n[RS274NGC]\nUSER_M_PATH = %s/user1:%s/user2\n' \
    "$work" "$work" "$work" > "$work/test.ini"
"$EMC2_HOME/objects/unit/interp_hooks_unit" "$work/test.ini" | sed "s|$work|WORK|"
