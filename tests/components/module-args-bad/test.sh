#!/bin/bash
# Module arguments that once loaded something wrong now fail the load with a clear message:
# names with blanks or empty entries, a negative count, an empty number; and encoder_ratio's names=/num_chan=0.
try() {
    echo "== loadrt $*"
    printf 'loadrt %s\nshow pin\n' "$*" > try.hal
    halrun -f try.hal 2>&1 | grep -v -e '^Note:' -e 'waitpid failed' -e 'without becoming ready' \
        -e 'insmod for' -e 'pretend' -e 'real hardware' -e 'Component Pins' -e 'Owner' -e '^$' \
        -e '\.time$' | sed 's/  */ /g'
    echo "exit ${PIPESTATUS[0]}"
    halrun -U >/dev/null 2>&1
}
try 'and2 names="a b"'
try 'and2 names=a,,b'
try 'and2 names=a,'
try 'and2 count=-1'
try 'stepgen step_type='
try 'stepgen step_type=0,,2'
try 'encoder names=a,,b'
try 'pid names="p 1"'
try 'siggen num_chan=-2'
try 'encoder_ratio num_chan=0'
try 'encoder_ratio names=er0'
try 'encoder_ratio num_chan=1 names=er0'
try 'encoder_ratio num_chan=9'
rm -f try.hal
