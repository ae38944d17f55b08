#!/bin/bash
# O-word structure: titles, forward-only M98, mixed Fanuc/rs274 styles, closing '%' during a
# search, nested and duplicate definitions. Prints the last canon lines, the exit status and
# the error text of each program.
run() {
    local f=$1; shift
    echo "== $f"
    rs274 -g "$@" "$f" 2> err.txt | awk '{$1=""; print}' | tail -n +7
    echo "exit ${PIPESTATUS[0]}"
    grep -v '^executing$' err.txt
    rm -f err.txt
}
for f in title-after-sub fall-into m98-forward m98-percent call-fanuc m98-rs274 fanuc-endsub \
         sub-m99 defined-twice call-percent; do
    run $f.ngc
done
run nested-in-file.ngc -i test.ini
run no-seek-in-sub.ngc -i test.ini
run disabled.ngc -i nofanuc.ini
exit 0
