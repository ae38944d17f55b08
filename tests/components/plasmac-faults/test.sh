#!/bin/bash
# plasmac faults: each scenario loads plasmac, reaches the point of the fault and shows the message,
# the state (15 = MAX_HEIGHT), the stop type (3 = PAUSE), the pause request and the torch.
# setup: a machine ready to cut in mode 1, motion applying the offsets at once (programmed Z 50)
setup() {
    cat <<'S'
load plasmac
functs plasmac
follow plasmac.z-offset-current plasmac.z-offset-counts plasmac.offset-scale
follow plasmac.axis-z-position plasmac.z-offset-counts plasmac.offset-scale 50
set plasmac.units-per-mm 1
set plasmac.machine-is-on 1
set plasmac.homed 1
set plasmac.torch-enable 1
set plasmac.mode 1
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
set plasmac.arc-fail-delay 0.002
set plasmac.restart-delay 0.001
set plasmac.program-is-running 1
S
}
# probe: start the cut and probe the material at once with the float switch (surface 1 below Z 50)
probe() {
    printf '%s\n' "set plasmac.cutting-start 1" "cycle 2" "set plasmac.float-switch 1" "cycle 1" \
        "set plasmac.float-switch 0" "cycle 3"
}
# cut: from pierce height with arc OK to cutting
cut() {
    printf '%s\n' "set plasmac.arc-ok-in 1" "cycle 6" "get plasmac.state-out"
}
status() {
    echo "trace 1 plasmac.state-out plasmac.stop-type-out plasmac.program-pause plasmac.torch-on"
}
run() {
    echo "== $1"
    shift
    { setup; "$@"; } | "$EMC2_HOME/objects/unit/comptest" | grep -v "^hal_init\|^rtapi_app_main"
}
sensor_first() { printf '%s\n' "set plasmac.float-switch 1" "set plasmac.cutting-start 1"; status; }
no_arc() { probe; echo "trace 8 plasmac.state-out plasmac.torch-on plasmac.pierce-count"; status; }
breakaway() { probe; cut; echo "set plasmac.breakaway 1"; status; }
float_in_cut() { probe; cut; echo "set plasmac.float-switch 1"; status; }
arc_lost() { probe; cut; echo "set plasmac.arc-ok-in 0"; status; status; }
arc_lost_delay() { echo "set plasmac.arc-lost-delay 0.003"; probe; cut; echo "set plasmac.arc-ok-in 0";
    echo "trace 3 plasmac.state-out plasmac.arc-ok-out"; status; }
bottom() { printf '%s\n' "set plasmac.axis-z-min-limit 49" "set plasmac.cutting-start 1" "cycle 2"; status; }
too_high() { echo "set plasmac.axis-z-max-limit 57"; probe; status; }
bad_height() { echo "set plasmac.cut-height 0"; probe; status; }
limit() { probe; cut; printf '%s\n' "set plasmac.offsets-active 1" "set plasmac.offsets-limited 1"; status; status; }
bad_volts() { printf '%s\n' "set plasmac.arc-voltage-in nan" "set plasmac.cutting-start 1"; echo "trace 3 plasmac.state-out";
    echo "cycle 997"; echo "trace 2 plasmac.state-out"; echo "set plasmac.arc-voltage-in 0"; echo "trace 1 plasmac.state-out"; }
low_volts() { printf '%s\n' "set plasmac.low-cut-volts 100" "set plasmac.thc-enable 1" "set plasmac.cut-feed-rate 60" \
    "set plasmac.feed-override 1" "set plasmac.current-velocity 2" "set plasmac.arc-voltage-in 120"; probe; cut;
    echo "trace 2 plasmac.thc-active plasmac.target-volts"; echo "set plasmac.arc-voltage-in 90"; status; }
thc_top() { printf '%s\n' "set plasmac.safe-height 40"; printf '%s\n' "set plasmac.thc-enable 1" "set plasmac.cut-feed-rate 60" "set plasmac.feed-override 1" \
    "set plasmac.current-velocity 2" "set plasmac.thc-feed-rate 600000" "set plasmac.pid-p-gain 1000" \
    "set plasmac.arc-voltage-in 120"; probe; cut; echo "cycle 2"; echo "set plasmac.arc-voltage-in 20";
    echo "trace 5 plasmac.state-out plasmac.z-offset-counts plasmac.safe-height-is-limited"; status; }
run "a sensor active before probing" sensor_first
run "no arc after arc-max-starts starts" no_arc
run "breakaway while cutting" breakaway
run "float switch while cutting" float_in_cut
run "arc lost while cutting (arc-lost-delay 0)" arc_lost
run "arc lost for arc-lost-delay 0.003 s" arc_lost_delay
run "probing reaches the bottom guard (Z min 49)" bottom
run "material too high: pierce height + 1 mm above the top (Z max 57, max-offset 5 mm)" too_high
run "cut height 0" bad_height
run "offset limit violation (reported once)" limit
run "NaN arc voltage: reported once a second, nothing runs" bad_volts
run "arc voltage below low-cut-volts with THC active" low_volts
run "THC reaching the top" thc_top
