#!/bin/bash
# Every module users load (rtlib/ except hal_lib, which rtapi_app loads itself) has a man9 page with a
# title, a NAME section naming it, a SYNOPSIS and a DESCRIPTION or PINS section.
top=${EMC2_HOME:?}
n=0
for so in "$top"/rtlib/*.so; do
    m=$(basename "$so" .so)
    [ "$m" = hal_lib ] && continue
    n=$((n + 1))
    page=$top/share/man/man9/$m.9
    if [ ! -f "$page" ]; then
        echo "no page: $m"
        continue
    fi
    for section in '^\.TH ' '^\.SH NAME' '^\.SH SYNOPSIS' '^\.SH \(DESCRIPTION\|PINS\)'; do
        grep -q "$section" "$page" || echo "$m.9: no ${section#^}"
    done
    sed -n '/^\.SH NAME/{n;p;}' "$page" | grep -q "^${m//-/\\\\-} \\\\-" || echo "$m.9: NAME does not start with $m"
done
[ "$n" -gt 150 ] && echo "modules checked: more than 150" || echo "modules checked: only $n"
