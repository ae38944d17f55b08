#!/bin/bash
# Every component of src/hal/components (.comp, hand-written module .c, doc/*.comp) has a man
# page share/man/man9/NAME.9 made by halcompile --document, with its NAME section.
cd "$EMC2_HOME" || exit 1
n=0
modules=$(grep -l '^int rtapi_app_main' src/hal/components/*.c)
for src in src/hal/components/*.comp $modules src/hal/components/doc/*.comp; do
    name=$(basename "${src%.*}")
    page=share/man/man9/$name.9
    if ! grep -q "^\.SH NAME" "$page" 2>/dev/null; then
        echo "missing or bad man page: $page"
    elif ! grep -q "^$name \\\\- " "$page"; then
        echo "man page $page does not name $name"
    else
        n=$((n + 1))
    fi
done
for src in $modules; do
    [ -e "src/hal/components/doc/$(basename "${src%.c}").comp" ] ||
        echo "no documentation source for $src"
done
[ "$n" -gt 100 ] && echo "man pages ok"
