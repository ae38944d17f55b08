#!/bin/bash
# Embedded Python in the interpreter: calls per second of a Python O-word subroutine, of a python= remap body
# and of an NGC remap with Python prolog and epilog (canon output to /dev/null).
set -e
TOP=$(cd "$(dirname "$0")/../../.." && pwd)
RS274=${RS274:-$TOP/bin/rs274}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
CALLS=${BENCH_CALLS:-100000}

cat > "$WORK/bench.ini" <<INI
[RS274NGC]
SUBROUTINE_PATH = $WORK
REMAP=M450 modalgroup=10 argspec=P python=body
REMAP=M451 modalgroup=10 argspec=P prolog=pro ngc=m451 epilog=epi
[PYTHON]
PATH_PREPEND = $WORK
TOPLEVEL = $WORK/toplevel.py
INI
printf 'import oword\nimport remap\n' > "$WORK/toplevel.py"
printf 'def twice(self, x):\n    return 2 * x\n' > "$WORK/oword.py"
cat > "$WORK/remap.py" <<PY
def body(self, **words):
    self.params["_last"] = words["p"]

def pro(self, **words):
    self.params["arg"] = words["p"]

def epi(self, **words):
    self.params["_last"] = self.return_value
PY
printf 'o<m451> sub\no<m451> endsub [#<arg>]\nM2\n' > "$WORK/m451.ngc"
for kind in "o<twice> call [1]" "M450 P1" "M451 P1"; do
    awk -v n="$CALLS" -v line="$kind" 'BEGIN { for (i = 0; i < n; i++) print line; print "M2" }' \
        > "$WORK/$(echo "$kind" | tr -dc 'a-zA-Z0-9').ngc"
done

# calls per second of one program
rate() {
    /usr/bin/time -f "%U %S" -o "$WORK/time" "$RS274" -i "$WORK/bench.ini" -g "$WORK/$1.ngc" > /dev/null 2> "$WORK/err" || { cat "$WORK/time" "$WORK/err" >&2; return 1; }
    awk -v n="$CALLS" -v what="$2" '{ s = $1 + $2; rate = 0; if (s != 0) rate = n / s; printf("rs274 %-32s %d calls: %.2f s CPU, %d calls/s\n", what, n, s, rate) }' "$WORK/time"
}
rate otwicecall1 "Python O-word sub"
rate M450P1 "python= remap body"
rate M451P1 "NGC remap, Python prolog+epilog"
