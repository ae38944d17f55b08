#!/bin/bash
# plasmac sensing and the jobs besides cutting: arc voltage (offset, scale, zero window, low-pass), mode 0 arc OK,
# ohmic sense debounce, jog inhibit, torch pulse, ohmic test, probe test, scribe, spotting, consumable change,
# cut recovery and paused motion.
setup() {
    cat <<'S'
load plasmac
functs plasmac
follow plasmac.z-offset-current plasmac.z-offset-counts plasmac.offset-scale
follow plasmac.axis-z-position plasmac.z-offset-counts plasmac.offset-scale 50
follow plasmac.x-offset-current plasmac.x-offset-counts plasmac.offset-scale
follow plasmac.y-offset-current plasmac.y-offset-counts plasmac.offset-scale
set plasmac.units-per-mm 1
set plasmac.machine-is-on 1
set plasmac.homed 1
set plasmac.torch-enable 1
set plasmac.axis-z-min-limit -100
set plasmac.axis-z-max-limit 100
set plasmac.axis-x-max-limit 1000
set plasmac.axis-y-max-limit 1000
set plasmac.setup-feed-rate 600000
set plasmac.probe-feed-rate 600000
set plasmac.float-switch-travel 1
set plasmac.pierce-height 4
set plasmac.cut-height 2
set plasmac.cut-volts 120
set plasmac.arc-voltage-scale 1
set plasmac.arc-max-starts 2
set plasmac.arc-fail-delay 0.01
set plasmac.program-is-idle 1
S
}
run() {
    echo "== $1"
    shift
    { setup; "$@"; } | "$EMC2_HOME/objects/unit/comptest" | grep -v "^hal_init\|^rtapi_app_main"
}
volts() { cat <<'S'
set plasmac.arc-voltage-offset 10
set plasmac.arc-voltage-scale 2
set plasmac.arc-voltage-in 70.25
trace 1 plasmac.arc-voltage-out
set plasmac.arc-voltage-in -10.02
trace 1 plasmac.arc-voltage-out
set plasmac.zero-window 1
trace 1 plasmac.arc-voltage-out
echo low-pass 100 Hz at 1 ms: 1 - exp(-2 pi 100 0.001) = 0.4665 of the step each period
set plasmac.arc-voltage-offset 0
set plasmac.arc-voltage-scale 1
set plasmac.arc-voltage-in 0
cycle
set plasmac.lowpass-frequency 100
set plasmac.arc-voltage-in 100
trace 2 plasmac.arc-voltage-out
S
}
mode0() { cat <<'S'
echo mode 0: arc OK once 3 samples agree within 5 V inside 60..200 V (only while the torch is on)
set plasmac.mode 0
set plasmac.ok-sample-counts 3
set plasmac.ok-sample-threshold 5
set plasmac.arc-ok-low 60
set plasmac.arc-ok-high 200
set plasmac.arc-voltage-in 100
set plasmac.torch-pulse-time 1
set plasmac.torch-pulse-start 1
cycle
set plasmac.torch-pulse-start 0
trace 4 plasmac.torch-on plasmac.arc-ok-out
echo out of the window and far from the target: lost after arc-lost-delay (0) at once
set plasmac.arc-voltage-in 250
trace 4 plasmac.arc-ok-out
S
}
ohmic() { cat <<'S'
echo ohmic sense: TRUE after more than 3 periods, FALSE after more than 3, only while ohmic-enable
set plasmac.ohmic-sense-in 1
trace 1 plasmac.ohmic-sense-out
set plasmac.ohmic-test 1
trace 5 plasmac.state-out plasmac.ohmic-enable plasmac.ohmic-sense-out
set plasmac.ohmic-sense-in 0
trace 4 plasmac.ohmic-sense-out
set plasmac.ohmic-test 0
trace 1 plasmac.state-out plasmac.ohmic-enable
echo jog inhibit while a sensor is active with the program idle, unless override-jog
set plasmac.breakaway 1
trace 1 plasmac.sensor-active plasmac.jog-inhibit
set plasmac.override-jog 1
trace 1 plasmac.jog-inhibit
S
}
pulse() { cat <<'S'
echo torch pulse of 3 ms, held longer while torch-pulse-hold
set plasmac.torch-pulse-time 0.003
set plasmac.torch-pulse-start 1
trace 1 plasmac.state-out plasmac.torch-on
set plasmac.torch-pulse-start 0
trace 4 plasmac.state-out plasmac.torch-on plasmac.torch-time
set plasmac.torch-pulse-start 1
set plasmac.torch-pulse-hold 1
cycle 10
trace 1 plasmac.state-out plasmac.torch-on
set plasmac.torch-pulse-hold 0
set plasmac.torch-pulse-start 0
trace 2 plasmac.state-out plasmac.torch-on
S
}
probetest() { cat <<'S'
echo probe test: probe, hold at pierce height while held, then every offset back to 0
set plasmac.probe-test 1
cycle 2
set plasmac.float-switch 1
cycle
set plasmac.float-switch 0
cycle 3
trace 1 plasmac.state-out plasmac.z-height plasmac.torch-on
set plasmac.probe-test 0
trace 3 plasmac.state-out plasmac.z-offset-counts
S
}
scribe() { cat <<'S'
echo scribe (multi-tool): arm, on after scribe-arm-delay, motion released after scribe-on-delay
set plasmac.scribe-arm-delay 0.002
set plasmac.scribe-on-delay 0.002
set plasmac.program-is-idle 0
set plasmac.program-is-running 1
set plasmac.scribe-start 1
trace 6 plasmac.state-out plasmac.scribe-arm plasmac.scribe-on plasmac.feed-hold
set plasmac.scribe-start 0
trace 1 plasmac.state-out plasmac.scribe-arm plasmac.scribe-on plasmac.feed-hold
S
}
spotting() { cat <<'S'
echo spotting: probe, pierce height, torch on; 2 ms after the voltage reaches 50 V the torch goes off
set plasmac.program-is-idle 0
set plasmac.program-is-running 1
set plasmac.mode 1
set plasmac.spotting-threshold 50
set plasmac.spotting-time 2
set plasmac.spotting-start 1
cycle 2
set plasmac.float-switch 1
cycle
set plasmac.float-switch 0
cycle 3
trace 2 plasmac.state-out plasmac.torch-on
set plasmac.arc-voltage-in 60
trace 4 plasmac.state-out plasmac.torch-on plasmac.stop-type-out
S
}
consumable() { cat <<'S'
echo paused by plasmac: consumable change moves XY to (x-offset, y-offset) counts while held, then back
set plasmac.program-is-idle 0
set plasmac.program-is-paused 1
set plasmac.xy-feed-rate 60000
set plasmac.x-offset 300000
set plasmac.y-offset -400000
set plasmac.consumable-change 1
trace 2 plasmac.state-out plasmac.consumable-changing
trace 5 plasmac.state-out plasmac.x-offset-counts plasmac.y-offset-counts
echo a sensor stops the move and is reported once
set plasmac.float-switch 1
cycle 2
set plasmac.float-switch 0
set plasmac.consumable-change 0
trace 6 plasmac.state-out plasmac.x-offset-counts plasmac.y-offset-counts plasmac.consumable-changing
S
}
recovery() { cat <<'S'
echo cut recovery while paused (stop type PAUSE after a fault): XY to the offsets at half cut speed
set plasmac.program-is-idle 0
set plasmac.program-is-running 1
set plasmac.cutting-start 1
set plasmac.breakaway 1
cycle 3
set plasmac.breakaway 0
set plasmac.program-is-running 0
set plasmac.program-is-paused 1
cycle 3
trace 1 plasmac.state-out plasmac.stop-type-out
set plasmac.cut-feed-rate 60000
set plasmac.x-offset 150000
set plasmac.cut-recovery 1
trace 3 plasmac.state-out plasmac.cut-recovering plasmac.x-offset-counts
echo released with an offset: idle with the offset kept until the cut restarts
set plasmac.cut-recovery 0
trace 2 plasmac.state-out plasmac.x-offset-counts plasmac.cut-recovering
echo paused motion: adaptive feed follows paused-motion-speed and the program is resumed
set plasmac.paused-motion-speed -0.5
trace 2 plasmac.state-out plasmac.paused-motion plasmac.adaptive-feed plasmac.program-resume plasmac.feed-hold
echo speed 0: pause again, adaptive feed 1, then back through cut recovery with the offset kept
set plasmac.program-is-paused 0
set plasmac.program-is-running 1
set plasmac.paused-motion-speed 0
trace 1 plasmac.state-out plasmac.paused-motion plasmac.adaptive-feed plasmac.program-pause
set plasmac.program-is-running 0
set plasmac.program-is-paused 1
trace 2 plasmac.state-out plasmac.x-offset-counts
S
}
run "arc voltage: (|in| - offset) * |scale|, rounded to 1 mV, 0 within the zero window" volts
run "mode 0 arc OK" mode0
run "ohmic sense and jog inhibit" ohmic
run "torch pulse" pulse
run "probe test" probetest
run "scribe" scribe
run "spotting" spotting
run "consumable change" consumable
run "cut recovery and paused motion" recovery
