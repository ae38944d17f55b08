#!/bin/bash
# stepgen: load errors, pins of each step type, moves, pulse timing, the 28-bit
# accumulator, direction holds (also a reversal long after the last step: dir
# must lead the first step by dirsetup), enable, ctrl_type words, and the phase
# sequence of every step type (2..15) forward and backward.
for s in script-noconf script-badctrl script-badtype script-userbad script-userbad2 \
         script-types script-types2 script-move script-timing script-round \
         script-dds script-reverse script-reverse-late script-updown script-enable \
         script-ctrlword; do
    echo "== $s"
    "$EMC2_HOME/objects/unit/comptest" < $s
done

# Print the distinct phase patterns (bit 0 = phase A) one channel goes through.
phases() {
    local type=$1 pins=$2 extra=$3 list="" p
    for p in A B C D E; do
        [ "$p" \> "$pins" ] && break
        list="$list stepgen.0.phase-$p"
    done
    {
        echo "load stepgen step_type=$type ctrl_type=v $extra"
        echo "period 100000"
        echo "functs stepgen.update-freq stepgen.make-pulses stepgen.capture-position"
        echo "set stepgen.0.enable 1"
        echo "set stepgen.0.velocity-cmd 2500"
        echo "trace 48 $list"
        echo "set stepgen.0.velocity-cmd -2500"
        echo "trace 48 $list"
    } | "$EMC2_HOME/objects/unit/comptest" | awk '
        /^rtapi_app_main/ || /^hal_init/ { next }
        { v = 0; for (i = NF; i >= 1; i--) v = v * 2 + $i }
        v != last { printf "%s%d", sep, v; sep = " "; last = v }
        END { print "" }'
}
for t in 2:B 3:C 4:C 5:D 6:D 7:D 8:D 9:D 10:D 11:E 12:E 13:E 14:E; do
    echo "== phases type ${t%:*}"
    phases "${t%:*}" "${t#*:}"
done
echo "== phases type 15"
phases 15 D "user_step_type=1,2,4,8,12"
