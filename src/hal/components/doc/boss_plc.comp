component boss_plc "PLC logic for a Bridgeport BOSS mill";
modparam dummy count "Number of instances (default 1; values above 4 become 4)";
modparam dummy debug "Non-zero adds the RO u32 params x-limit-state, y-limit-state and spindle-state";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Instances boss_plc.N, each with one function boss_plc.N.refresh, which runs in order:

Feed: feed-hold-out latches on cycle-hold-in, on a spindle speed without spindle-is-on-in,
or on a speed change while the spindle runs, until a rising edge of cycle-start-in.
adaptive-feed-out is 0.01 under limit-override-in, else adaptive-feed-in. Tool change
handshake (tool-change-in, tool-changed-out, wait-user-out); mist and flood are held off
during a tool change.

Limits: X and Y have one shared switch each (x-limit-in, y-limit-in); the end that was hit
follows from the direction of travel (x-position-in, y-position-in). Z has its own switches.
Jogging an axis with limit-override-in masks its limit outputs. limit-active-out is the OR
of the raw switch inputs.

Amps (x, y, z, a): L-amp-fault-out is TRUE when the amp is enabled and not ready
amp-ready-delay milliseconds after enable rose.

Spindle: releases the brake (brake-off-delay ms), runs forward or reverse depending on the
gear range (spindle-lo-to-hi), waits for spindle-is-on-in, and applies the brake
(brake-on-delay ms) after it stops. spindle-inc-out/-dec-out pass while it runs.

Jog: the first TRUE of jog-sel-in-0/1/2 copies jog-scale-0/1/2 to jog-scale-out.""";
