#!/bin/bash
# Every module of rtlib/ loads and shows its pins, params and functs as checked in (expected): the
# components together in one realtime session, each kinematics module in a session of its own (they
# share pin and export names). A pin renamed, retyped, redirected or given another default shows here.
top=${EMC2_HOME:?}
args() { awk -v m="$1" '$1 == m { $1 = ""; sub(/^ /, ""); print }' args.txt; }
# session NAME...: load the modules, print what HAL shows, stop
session() {
    realtime start >/dev/null 2>&1 || { echo "realtime start failed"; return; }
    for m in "$@"; do
        # shellcheck disable=SC2046
        halcmd loadrt "$m" $(args "$m") >/dev/null 2>&1 || echo "load failed: $m"
    done
    # the owner ids depend on how many components came before: left out, so a new module changes
    # only its own lines
    { halcmd show pin; halcmd show param; } | sed -E 's/^ +[0-9]+  +//'
    halcmd list funct | tr ' ' '\n' | grep -v '^$'
    realtime stop >/dev/null 2>&1
}
trap 'realtime stop >/dev/null 2>&1' EXIT
realtime stop >/dev/null 2>&1
skip=$(awk '!/^#/ && NF { print $1 }' elsewhere.txt)
mods=$(cd "$top/rtlib" && ls ./*.so | sed 's|^\./||; s|\.so$||' | grep -v '^hal_lib$' |
    grep -vxF -f <(printf '%s\n' $skip))
kins=$(printf '%s\n' $mods | grep -E 'kins|trsrn|^millturn$')
comps=$(printf '%s\n' $mods | grep -vxF -f <(printf '%s\n' $kins))
echo "== components"
session $comps
for k in $kins; do
    echo "== $k"
    session "$k"
done
