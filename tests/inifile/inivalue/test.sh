# inivalue: typed output, ranges, --all/--num, listings with escaped content, boolean styles and exit codes (0-3).
. "$TEST_DIR/../lib.sh"
# v ARGS...: inivalue with its output and exit status
v() { with_status inivalue "$@"; }
v --var=MACHINE values.ini
HOME=/home/tester v --var PATH --tildeexpand values.ini
with_status env -u HOME inivalue --var PATH --tildeexpand values.ini
v --var MAX_VELOCITY --type=r values.ini
v --var COUNT --type=i values.ini
v --var HEX --type=u values.ini
v --var NEG --type=u values.ini
v --var FLAG --type=b values.ini
v --var FLAG --type=b --boolnum values.ini
v --var FLAG --type=b -b values.ini
v --var FLAG --type=b --boolpy values.ini
v --var FLAG --type=b -B values.ini
v --var WORD --type=r values.ini
v --var WORD --type=b values.ini
# ranges: -m/-M after --type, parsed in that type (negative unsigned limits wrap)
v --var MAX_VELOCITY --type=r --minimum=0 --maximum=3 values.ini
v --var MAX_VELOCITY --type=r -m 3.5 -M 3.5 values.ini
v --var COUNT --type=i --minimum=12 --maximum=12 values.ini
v --var NEG --type=i -m 0 -M 5 values.ini
v --var NEG --type=i -m 0 -M -5 values.ini
v --var NEG --type=u -m -2 -M -1 values.ini
v --var HEX --type=u -m 0x21 values.ini
v --var HEX --type=r -m 1 -M 0 values.ini
v --var HEX -m 1 values.ini
v --var HEX --type=i -m 1x values.ini
# --all from the --num-th on, and past the last one
v --var HALFILE --all values.ini
v --var HALFILE --all --num=2 values.ini
v --var HALFILE --all --num=3 values.ini
v --var NOSUCH --all --num=2 values.ini
v --var HALFILE --num=2 values.ini
v --var HALFILE --num=3 values.ini
v --var WORD --sec=EMC values.ini
v --var WORD --sec=EMC --quiet values.ini
# listings
v --sections values.ini
v --variables --sec HAL values.ini
v --variables --prefix --sec HAL values.ini
v --variables --content --sec EMC values.ini
v --content --sec NOPE values.ini
v --variables --content --sec ESCAPED values.ini
# --content output reads back as the same values
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for s in $(inivalue --sections values.ini); do
    echo "[$s]"
    inivalue --variables --content --sec "$s" values.ini
done > "$work/copy.ini"
for k in LEAD TAIL CTRL SLASH; do
    [ "$(inivalue --var $k values.ini | od -c)" = "$(inivalue --var $k "$work/copy.ini" | od -c)" ] && echo "$k reads back"
done
# usage errors
v values.ini
v --var X
v --var X a.ini b.ini
v --var X --type=z values.ini
v --var X --num=0 values.ini
v --var X --type=i --minimum=abc values.ini
v --var X --bogus values.ini
v --var X no-such.ini
v --help | tail -n 2
