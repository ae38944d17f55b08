#!/bin/bash
# loadusr -W/-Wn with a real user component, show comp User lines, waitusr, unloadusr, unload.
realtime start 2> /dev/null || exit 1
export UC="$EMC2_HOME/objects/unit/halcmd_usercomp"
halcmd -k -f 2>&1 <<'HAL' | sed -E -e 's/^( +[0-9]+  User  .{55}) +[0-9]+ /\1 PID /' -e '/ halcmd[0-9]/d'
loadusr -Wn uc1 $(UC) uc1
loadusr -W $UC halcmd_usercomp
getp uc1.out
show comp
list comp uc
net s1 uc1.out
gets s1
waitusr uc1x
unloadusr uc1
waitusr uc1
list comp uc
unload halcmd_usercomp
waitusr halcmd_usercomp
list comp uc
gets s1
loadusr -Wn uc3 $UC uc3
loadusr -Wn uc4 $UC uc4
unload all
waitusr uc3
waitusr uc4
list comp uc
HAL
echo "exit ${PIPESTATUS[0]}"
realtime stop
