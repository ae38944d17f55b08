#!/bin/bash
# Edge values that once gave undefined C or drifting results: each case loads one module in the fake HAL.
run() { "$EMC2_HOME/objects/unit/comptest" | grep -v '^hal_init\|^rtapi_app_main'; }
echo "time: ten 100 ms periods are exactly one second (integer ns, no float drift)"
run <<'S'
load time
functs time.0
period 100000000
set time.0.start 1
cycle 9
get time.0.seconds
cycle 1
get time.0.seconds
S
echo "pwmgen: a negative value with the pwm-only output gives curr-dc 0, not -0"
run <<'S'
load pwmgen output_type=0
functs pwmgen.update
set pwmgen.0.enable 1
set pwmgen.0.value -0.5
cycle 1
get pwmgen.0.curr-dc
set pwmgen.0.enable 0
cycle 1
get pwmgen.0.curr-dc
S
echo "abs_s32/abs_s64: the most negative value saturates"
run <<'S'
load abs_s32
functs abs-s32.0
set abs-s32.0.in -2147483648
cycle 1
get abs-s32.0.out abs-s32.0.sign
S
run <<'S'
load abs_s64
functs abs-s64.0
set abs-s64.0.in -9223372036854775808
cycle 1
get abs-s64.0.out abs-s64.0.sign
S
echo "conv_float_u64: exactly 2^64 and NaN are out of range, clamped or not"
run <<'S'
load conv_float_u64 count=2
functs conv-float-u64.0 conv-float-u64.1
set conv-float-u64.1.clamp 1
set conv-float-u64.0.in 18446744073709551616
set conv-float-u64.1.in 18446744073709551616
cycle 1
get conv-float-u64.0.out conv-float-u64.0.out-of-range conv-float-u64.1.out conv-float-u64.1.out-of-range
set conv-float-u64.0.in nan
set conv-float-u64.1.in nan
cycle 1
get conv-float-u64.0.out conv-float-u64.0.out-of-range conv-float-u64.1.out conv-float-u64.1.out-of-range
set conv-float-u64.0.in -2.5
cycle 1
get conv-float-u64.0.out conv-float-u64.0.out-of-range
S
echo "conv_float_s64 and conv_float_s32: +2^63 / +2^31 clamp to the maximum, -inf to the minimum"
run <<'S'
load conv_float_s64
functs conv-float-s64.0
set conv-float-s64.0.clamp 1
set conv-float-s64.0.in 9223372036854775808
cycle 1
get conv-float-s64.0.out conv-float-s64.0.out-of-range
S
run <<'S'
load conv_float_s32
functs conv-float-s32.0
set conv-float-s32.0.clamp 1
set conv-float-s32.0.in 2147483648
cycle 1
get conv-float-s32.0.out conv-float-s32.0.out-of-range
set conv-float-s32.0.in -inf
cycle 1
get conv-float-s32.0.out conv-float-s32.0.out-of-range
set conv-float-s32.0.clamp 0
set conv-float-s32.0.in nan
cycle 1
get conv-float-s32.0.out conv-float-s32.0.out-of-range
S
echo "biquad: a NaN Q is refused (valid 0, out follows in)"
run <<'S'
load biquad
functs biquad.0
set biquad.0.type 1
set biquad.0.Q nan
set biquad.0.in 3
set biquad.0.enable 1
cycle 2
get biquad.0.valid biquad.0.out
S
echo "ilowpass: a result beyond s32 wraps (low 32 bits of the 64-bit result, as LinuxCNC)"
run <<'S'
load ilowpass
functs ilowpass.0
set ilowpass.0.gain 1
set ilowpass.0.in 3000000
cycle 1
get ilowpass.0.out
set ilowpass.0.in -3000000
cycle 1
get ilowpass.0.out
S
echo "siggen: NaN and -inf frequencies hold the phase; the waves recover at once"
run <<'S'
load siggen
functs siggen.0.update
period 250000000
cycle 1
get siggen.0.sawtooth
set siggen.0.frequency nan
cycle 1
get siggen.0.sawtooth
set siggen.0.frequency -inf
cycle 1
get siggen.0.sawtooth
set siggen.0.frequency 1
cycle 1
get siggen.0.sawtooth siggen.0.square
set siggen.0.frequency -1e300
cycle 1
get siggen.0.sawtooth
S
echo "limit3: a short move still obeys maxv (1 unit per 1 ms period at maxv 1000)"
run <<'S'
load limit3
functs limit3.0
set limit3.0.maxv 1000
set limit3.0.in 5
trace 3 limit3.0.out
S
echo "knob2float: counts wrapping past the s32 limit are one step"
run <<'S'
load knob2float
functs knob2float.0
set knob2float.0.enable 1
set knob2float.0.scale 0.1
set knob2float.0.max-out 100
set knob2float.0.counts 2147483647
cycle 1
set knob2float.0.counts -2147483648
cycle 1
get knob2float.0.out
S
echo "mux_generic: a selection beyond 2^31 picks the last input"
run <<'S'
load mux_generic config=ff4
functs mux-gen.00
set mux-gen.00.in-float-01 7
set mux-gen.00.sel-int 1
cycle 1
set mux-gen.00.sel-int 4294967295
cycle 2
get mux-gen.00.out-float mux-gen.00.selected
S
echo "scaled_s32_sums: a sum beyond s32 saturates"
run <<'S'
load scaled_s32_sums
functs scaled-s32-sums.0
set scaled-s32-sums.0.in0 2000000000
set scaled-s32-sums.0.scale0 2
cycle 1
get scaled-s32-sums.0.out-s
set scaled-s32-sums.0.scale0 -2
cycle 1
get scaled-s32-sums.0.out-s
S
echo "xhc_hb04_util: an inf scale saturates the output and leaves the filter unharmed"
run <<'S'
load xhc_hb04_util
functs xhc-hb04-util.0
set xhc-hb04-util.0.in0 10
cycle 1
get xhc-hb04-util.0.out0
set xhc-hb04-util.0.scale0 inf
cycle 1
get xhc-hb04-util.0.out0
set xhc-hb04-util.0.scale0 1
set xhc-hb04-util.0.in0 4
cycle 1
get xhc-hb04-util.0.out0
S
echo "weighted_sum: a sum past the s32 range wraps like a 32-bit register"
run <<'S'
load weighted_sum wsum_sizes=2
functs process_wsums
set wsum.0.offset 2147483647
set wsum.0.bit.0.in 1
cycle 1
get wsum.0.sum
S
echo "laserpower: a NaN current velocity scales to 0 (power = min-power)"
run <<'S'
load laserpower
functs laserpower.0
set laserpower.0.enabled 1
set laserpower.0.raster-mode 1
set laserpower.0.raster-power 50
set laserpower.0.max-power 100
set laserpower.0.min-power 2
set laserpower.0.req-velocity 100
set laserpower.0.cur-velocity nan
cycle 1
get laserpower.0.power laserpower.0.vel-scale
S
echo "mux16: out-s saturates beyond s32 and gives 0 for NaN"
run <<'S'
load mux16
functs mux16.0
set mux16.0.in00 1e12
cycle 1
get mux16.0.out-s
set mux16.0.in00 -1e12
cycle 1
get mux16.0.out-s
set mux16.0.in00 nan
cycle 1
get mux16.0.out-s
S
echo "safety_latch: harm past the s32 range saturates the count instead of wrapping"
run <<'S'
load safety_latch
functs safety-latch.0
set safety-latch.0.max 2147483647
set safety-latch.0.threshold 2147483647
set safety-latch.0.harm 2147483647
set safety-latch.0.error-in 1
cycle 2
get safety-latch.0.count safety-latch.0.ok-out safety-latch.0.error-out
S
echo "demux_generic: NaN to an s32 output is 0, a huge float saturates"
run <<'S'
load demux_generic config=fs2
functs demux-gen.00
set demux-gen.00.in-float nan
cycle 1
get demux-gen.00.out-s32-00
set demux-gen.00.in-float 1e300
cycle 1
get demux-gen.00.out-s32-00
S
echo "stepgen: a NaN position command ramps the rate down and the channel still follows later commands"
run <<'S'
load stepgen step_type=0
period 100000
functs stepgen.update-freq stepgen.make-pulses stepgen.capture-position
set stepgen.0.position-scale 100
set stepgen.0.maxvel 20
set stepgen.0.maxaccel 2000
set stepgen.0.enable 1
set stepgen.0.position-cmd 0.05
cycle 20
set stepgen.0.position-cmd nan
cycle 1
get stepgen.0.frequency
cycle 400
get stepgen.0.frequency
set stepgen.0.position-cmd -0.02
cycle 400
get stepgen.0.counts stepgen.0.frequency
S
echo "stepgen: a NaN velocity command ramps down to 0; a NaN maxaccel or scale means the default"
run <<'S'
load stepgen step_type=0 ctrl_type=v
period 100000
functs stepgen.update-freq stepgen.make-pulses stepgen.capture-position
set stepgen.0.maxaccel 20000
set stepgen.0.enable 1
set stepgen.0.velocity-cmd 1000
cycle 100
set stepgen.0.velocity-cmd nan
cycle 50
get stepgen.0.frequency
cycle 50
get stepgen.0.frequency
set stepgen.0.maxaccel nan
set stepgen.0.position-scale nan
set stepgen.0.velocity-cmd 500
cycle 1
get stepgen.0.frequency stepgen.0.maxaccel stepgen.0.position-scale
S
echo "pwmgen: a NaN value is off and leaves no stuck state; a tiny pwm-freq gives a long finite cycle"
run <<'S'
load pwmgen output_type=0
period 1000000
functs pwmgen.update pwmgen.make-pulses
set pwmgen.0.enable 1
set pwmgen.0.value nan
cycle 3
get pwmgen.0.curr-dc pwmgen.0.pwm
set pwmgen.0.value 1
trace 2 pwmgen.0.pwm
set pwmgen.0.value 0.25
set pwmgen.0.pwm-freq 1e-300
trace 2 pwmgen.0.pwm
S
echo "sim_encoder: a NaN speed stops the counts"
run <<'S'
load sim_encoder
period 1000000
functs sim-encoder.update-speed sim-encoder.make-pulses
set sim-encoder.0.ppr 2
set sim-encoder.0.speed 62.5
cycle 10
get sim-encoder.0.rawcounts
set sim-encoder.0.speed nan
trace 4 sim-encoder.0.rawcounts
set sim-encoder.0.speed -62.5
cycle 10
get sim-encoder.0.rawcounts
S
echo "watchdog: a NaN timeout counts as expired, so ok-out drops"
run <<'S'
load watchdog num_inputs=1
period 100000000
functs watchdog.set-timeouts watchdog.process
set watchdog.timeout-0 nan
set watchdog.enable-in 1
cycle 1
get watchdog.ok-out
S
echo "oneshot: a NaN width gives no pulse, and the next trigger with a valid width works"
run <<'S'
load oneshot
period 100000000
functs oneshot.0
set oneshot.0.retriggerable 0
set oneshot.0.width nan
set oneshot.0.in 1
cycle 1
get oneshot.0.out oneshot.0.time-left
set oneshot.0.in 0
set oneshot.0.width 0.25
cycle 1
set oneshot.0.in 1
cycle 1
get oneshot.0.out oneshot.0.time-left
S
echo "sim_spindle: a NaN or infinite velocity does not move the spindle"
run <<'S'
load sim_spindle
period 100000000
functs sim-spindle.0
set sim-spindle.0.velocity-cmd 3
cycle 1
set sim-spindle.0.velocity-cmd nan
cycle 1
get sim-spindle.0.position-fb
set sim-spindle.0.velocity-cmd inf
cycle 1
set sim-spindle.0.velocity-cmd 3
cycle 1
get sim-spindle.0.position-fb
S
echo "thcud: a NaN correction-vel makes no correction instead of a NaN Z command"
run <<'S'
load thcud
functs thcud
set thcud.current-vel 10
set thcud.requested-vel 10
set thcud.torch-on 1
set thcud.arc-ok 1
set thcud.enable 1
set thcud.torch-up 1
set thcud.z-pos-in 5
set thcud.correction-vel nan
cycle 1
set thcud.correction-vel 0.5
set thcud.torch-on 0
cycle 1
get thcud.z-pos-out thcud.removing-offset
S
echo "plasmac: a NaN probe-start-height probes from the current height"
run <<'S'
load plasmac
functs plasmac
set plasmac.machine-is-on 1
set plasmac.torch-enable 1
set plasmac.axis-z-min-limit 0
set plasmac.axis-z-max-limit 100
set plasmac.axis-z-position 50
set plasmac.setup-feed-rate 60000
set plasmac.probe-feed-rate 600
set plasmac.probe-start-height nan
set plasmac.homed 1
set plasmac.units-per-mm 1
set plasmac.pierce-height 4
set plasmac.cut-height 1.5
set plasmac.mode 1
set plasmac.program-is-running 1
set plasmac.cutting-start 1
trace 3 plasmac.state-out plasmac.z-offset-counts
S
echo "knob2float: a NaN scale holds the output, which then follows the counts again"
run <<'S'
load knob2float
functs knob2float.0
set knob2float.0.max-out 100
set knob2float.0.enable 1
set knob2float.0.scale 0.5
cycle 1
set knob2float.0.counts 4
cycle 1
set knob2float.0.scale nan
set knob2float.0.counts 6
cycle 1
get knob2float.0.out
set knob2float.0.scale 0.5
set knob2float.0.counts 8
cycle 1
get knob2float.0.out
S
echo "plasmac: a NaN torch-pulse-time ends the pulse at once instead of leaving the torch on"
run <<'S'
load plasmac
functs plasmac
set plasmac.machine-is-on 1
set plasmac.torch-enable 1
set plasmac.axis-z-min-limit 0
set plasmac.axis-z-max-limit 100
set plasmac.axis-z-position 50
set plasmac.program-is-idle 1
set plasmac.torch-pulse-time nan
set plasmac.torch-pulse-start 1
trace 3 plasmac.state-out plasmac.torch-on
S
echo "limit3: a NaN input brakes and holds; a NaN maxa is no acceleration, not a stuck NaN"
run <<'S'
load limit3
functs limit3.0
period 1000000
set limit3.0.maxv 100
set limit3.0.maxa 1000
set limit3.0.in 1
cycle 20
set limit3.0.in nan
cycle 500
get limit3.0.out
set limit3.0.in 0.5
cycle 500
get limit3.0.out
set limit3.0.maxa nan
set limit3.0.in 0.75
cycle 10
get limit3.0.out
S
