#!/bin/bash
# One line with the spindle.0 output pins.
printf 'on=%s fwd=%s rev=%s brake=%s orient=%s locked=%s out=%s rps=%s cmd-rps=%s\n' \
    "$(halcmd getp spindle.0.on)" "$(halcmd getp spindle.0.forward)" "$(halcmd getp spindle.0.reverse)" \
    "$(halcmd getp spindle.0.brake)" "$(halcmd getp spindle.0.orient)" "$(halcmd getp spindle.0.locked)" \
    "$(halcmd getp spindle.0.speed-out)" "$(halcmd getp spindle.0.speed-out-rps)" "$(halcmd getp spindle.0.speed-cmd-rps)"
