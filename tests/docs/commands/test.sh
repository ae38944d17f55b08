#!/bin/bash
# commands: every program in bin/ answers --help (usage on stdout, exit 0; inivalue 1 as LinuxCNC's)
# without starting anything, and has a man page share/man/man1/NAME.1 that renders without
# warnings; the scripts in scripts/ answer --help too. Only problems are printed.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
# check_help PATH: run PATH --help in an empty HOME; complain unless it prints a usage and exits
# with the expected status
check_help() {
    local prog=$1 name want=0 out rc
    name=$(basename "$prog")
    [ "$name" = inivalue ] && want=1
    out=$(cd "$home" && HOME=$home timeout 20 "$prog" --help < /dev/null 2> "$home/err")
    rc=$?
    [ "$rc" = "$want" ] || echo "$name --help: exit status $rc, not $want"
    grep -qi usage <<< "$out" || echo "$name --help: no usage text on stdout"
}
for prog in "$EMC2_HOME"/bin/*; do
    [ -x "$prog" ] || continue
    name=$(basename "$prog")
    check_help "$prog"
    page=$EMC2_HOME/share/man/man1/$name.1
    if [ ! -f "$page" ]; then
        echo "$name: no man page share/man/man1/$name.1"
        continue
    fi
    warnings=$(MANWIDTH=80 man --warnings=all -l "$page" 2>&1 > "$home/page")
    [ -z "$warnings" ] || echo "$name.1: $warnings"
    grep -q "^NAME" "$home/page" && grep -qF -- "$name" "$home/page" || echo "$name.1: no NAME section naming it"
done
for prog in "$EMC2_HOME"/scripts/*; do
    case $(basename "$prog") in rip-environment|*.py|*.supp) continue ;; esac
    check_help "$prog"
done
# nothing may have started a realtime master of this instance
realtime status > /dev/null 2>&1 && echo "a realtime master was started" && realtime stop
echo done
