#!/bin/bash
# max31855: clock and chip select timing (65 calls reading, 65 idle), a frame bit-banged MSB first,
# cold-junction correction, and a fault frame. The script is generated: one data level per call.
frame_script() {   # frame_script W: set the data line for each call of one read phase (call 2k gives bit 32-k)
    local w=$1 step bit
    for step in $(seq 0 64); do
        bit=0
        if [ $((step % 2)) -eq 0 ] && [ $step -ge 2 ]; then bit=$(( (w >> (32 - step / 2)) & 1 )); fi
        echo "set max31855.0.data.0.in $bit"
        echo "cycle 1"
    done
    echo "get max31855.0.cs.out max31855.0.clk.out"
    echo "cycle 65"
}
# thermocouple 100.25 C (401 quarter degrees in w[31:18]), cold junction 25 C (400 sixteenths in w[15:4])
good=$(( (401 << 18) | (400 << 4) ))
{
    echo "load max31855 personality=1"
    echo "functs max31855.0.bitbang-spi"
    frame_script $good
    echo "get max31855.0.temp-celsius.0 max31855.0.temp-fahrenheit.0 max31855.0.temp-kelvin.0 max31855.0.fault.0"
    frame_script $(( good | 1 ))
    echo "get max31855.0.fault.0 max31855.0.fault-flags.0 max31855.0.temp-celsius.0"
} | "$EMC2_HOME/objects/unit/comptest"
echo "== personality 16"
echo "load max31855 personality=16" | "$EMC2_HOME/objects/unit/comptest"
