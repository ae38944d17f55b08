#!/bin/bash
# hm2-test-patterns: hm2_test's register images walk hm2_register through every IDROM check
# (first error line of each pattern, on stderr at the default message level), pattern 12 registers
# a board without modules, and firmware= is looked up, checked against the FPGA and programmed.
. ../lib.sh
rt_start
halcmd loadrt hostmot2 || exit 1

# load ARGS...: one hm2_test load; prints the exit status and the first hm2 error line after it.
load() {
    local before
    before=$(wc -l < "$RT_LOG")
    halcmd loadrt hm2_test "$@" > /dev/null 2>&1
    echo "$* -> status $?"
    tail -n +"$((before + 1))" "$RT_LOG" | grep -E '^hm2(_test)?[/.:]' | grep -vE 'Low Level|loading|IDRom|    |no firmware|fails HM2|Pin Desc' | head -n 1 | sed "s|$HM2_TMP|TMP|g"
    halcmd unloadrt hm2_test > /dev/null 2>&1
}
for p in 0 1 2 3 4 5 6 7 8 9 10 11 13 14 15; do load test_pattern=$p; done

before=$(wc -l < "$RT_LOG")
halcmd loadrt hm2_test test_pattern=12 || exit 1
echo "pattern 12: $(halcmd list pin 'hm2_test.0.*' | wc -w) pins, $(halcmd list param 'hm2_test.0.gpio.*' | wc -w) gpio params"
show_items funct 'hm2_test*'
tail -n +"$((before + 1))" "$RT_LOG" | grep -E 'invalid pin number 0$|IO Pin 0(00|23)|registered|initialized'
halcmd unloadrt hm2_test
tail -n 2 "$RT_LOG"

export OPENEMC_FIRMWARE_DIR="$HM2_TMP/fw"
mkdir -p "$OPENEMC_FIRMWARE_DIR/hm2"
# bitfile NAME PART: a minimal Xilinx .bit file for FPGA PART.
bitfile() {
    local part=$2
    {
        printf '\x00\x09\x0f\xf0\x0f\xf0\x0f\xf0\x0f\xf0\x00\x00\x01'
        printf 'a\x00\x05test\x00'
        printf "b\\x00\\x$(printf %02x $(( ${#part} + 1 )))%s\\x00" "$part"
        printf 'c\x00\x0b2024/01/01\x00d\x00\x0900:00:00\x00e\x00\x00\x00\x04\xde\xad\xbe\xef'
    } > "$OPENEMC_FIRMWARE_DIR/hm2/$1"
}
halcmd stop > /dev/null 2>&1; halcmd unload all > /dev/null 2>&1; realtime stop > /dev/null 2>&1
rt_start
halcmd loadrt hostmot2 || exit 1
bitfile wrong.bit 6slx9tqg144
bitfile right.bit none
printf 'not a bitfile' > "$OPENEMC_FIRMWARE_DIR/hm2/junk.bit"
load test_pattern=12 config=firmware=hm2/missing.bit
load test_pattern=12 config=firmware=hm2/wrong.bit
load test_pattern=12 config=firmware=hm2/junk.bit
load test_pattern=12 config=firmware=hm2/an_image_name_longer_than_30.bit
before=$(wc -l < "$RT_LOG")
halcmd loadrt hm2_test test_pattern=12 config=firmware=hm2/right.bit && echo "matching firmware programs and registers"
halcmd unloadrt hm2_test
