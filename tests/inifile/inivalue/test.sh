# inivalue: typed output, ranges, listings, --all/--prefix and its exit codes (0, 1, 2, 3).
. "$TEST_DIR/../lib.sh"
# v ARGS...: inivalue with its output and exit status
v() { with_status inivalue "$@"; }
v --var=MACHINE values.ini
HOME=/home/tester v --var PATH --tildeexpand values.ini
v --var MAX_VELOCITY --type=r values.ini
v --var COUNT --type=i values.ini
v --var HEX --type=u values.ini
v --var NEG --type=u values.ini
v --var FLAG --type=b values.ini
v --var FLAG --type=b --boolnum values.ini
v --var FLAG --type=b --boolpy values.ini
v --var WORD --type=r values.ini
v --var WORD --type=b values.ini
v --var MAX_VELOCITY --type=r --minimum=0 --maximum=3 values.ini
v --var COUNT --type=i --minimum=12 --maximum=12 values.ini
v --var HALFILE --all values.ini
v --var HALFILE --num=2 --prefix values.ini
v --var HALFILE --num=3 values.ini
v --var WORD --sec=EMC values.ini
v --var WORD --sec=EMC --quiet values.ini
v --sections values.ini
v --variables --sec HAL values.ini
v --content --sec EMC values.ini
v --content --sec NOPE values.ini
v values.ini
v --var X
v --var X --type=z values.ini
v --var X --num=0 values.ini
v --var X --minimum=abc values.ini
v --var X --bogus values.ini
v --var X no-such.ini
v --help | tail -n 2
