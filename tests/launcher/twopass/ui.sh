#!/bin/bash
# display: the merged loads and the wiring made in pass 1
halcmd -s show comp | awk 'NF >= 3 && $2 == "RT" {print $3}' | sort | tr '\n' ' '; echo
halcmd list pin not.2.out; echo
echo "lp2.gain=$(halcmd getp lp2.gain)"
halcmd save thread | grep addf
halcmd -s show sig ab
