#!/bin/bash
# alias/unalias of pins and params: lookups by both names, listings, save.
realtime start 2> /dev/null || exit 1
halcmd -k -f 2>&1 <<'HAL'
loadrt sum2
alias pin sum2.0.in0 first-input
alias param sum2.0.gain0 first-gain
alias pin nosuch x
alias pin sum2.0.in1 sum2.0.out
alias thing sum2.0.in1 x
setp first-input 2
getp sum2.0.in0
setp sum2.0.gain0 3
getp first-gain
net sig1 first-input
show pin
show param
show alias
show alias sum2.0.in
save alias
save netla
list pin
alias pin first-input second-name
show alias
unalias pin second-name
unalias param sum2.0.gain0
show alias
list pin
HAL
echo "exit $?"
realtime stop
