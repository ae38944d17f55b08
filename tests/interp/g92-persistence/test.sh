#!/bin/bash
# G92 offsets persist through the .var file unless DISABLE_G92_PERSISTENCE = 1.
status=0
for mode in on off; do
    printf '5210\t1.0\n5211\t0.5\n' > p.var
    rs274 -i $mode.ini -v p.var -g test.ngc | awk '{$1=""; print}' | grep -E 'G92|MESSAGE'
    [ "${PIPESTATUS[0]}" = 0 ] || status=1
    grep -E '^521[01]' p.var
done
rm -f p.var p.var.bak
exit $status
