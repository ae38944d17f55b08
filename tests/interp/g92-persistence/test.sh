#!/bin/bash
# G92 offsets persist through the .var file (any non-zero #5210 restores them, A B C unscaled)
# unless DISABLE_G92_PERSISTENCE = 1.
status=0
for mode in on off; do
    printf '5210\t2.0\n5211\t0.5\n5214\t2.0\n' > p.var
    rs274 -i $mode.ini -v p.var -g test.ngc | awk '{$1=""; print}' | grep -E 'G92|MESSAGE'
    [ "${PIPESTATUS[0]}" = 0 ] || status=1
    grep -E '^521[01]' p.var
done
rm -f p.var p.var.bak
exit $status
