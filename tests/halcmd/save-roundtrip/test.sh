#!/bin/bash
# save allu output reloaded into a fresh HAL reproduces the same show output and the same save.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
halcmd -f setup.hal || exit 1
halcmd save allu > saved1.tmp.hal
for t in pin sig param alias thread; do halcmd show $t; done > show1.tmp
halcmd save > saved1-default.tmp
realtime stop
realtime start 2> /dev/null || exit 1
halcmd -f saved1.tmp.hal || exit 1
halcmd save allu > saved2.tmp.hal
for t in pin sig param alias thread; do halcmd show $t; done > show2.tmp
realtime stop
cat saved1.tmp.hal
echo "--- save (default all)"
cat saved1-default.tmp
cmp saved1.tmp.hal saved2.tmp.hal && echo "save output identical"
cmp show1.tmp show2.tmp && echo "show output identical"
echo "--- other save types"
realtime start 2> /dev/null || exit 1
halcmd -f setup.hal || exit 1
for t in comp sig sigu link linka net neta netl netal param thread unconnectedinpins; do
    echo "> save $t"
    halcmd save $t
done
halcmd save bogus 2>&1
halcmd save sig saved-sig.tmp && cat saved-sig.tmp
halcmd save sig /nonexistent/dir/x 2>&1
halcmd unalias pin second-and-in
halcmd unalias param sum-offset
echo "> save alias, none left: the headers stay"
halcmd save alias
realtime stop
rm -f ./*.tmp ./*.tmp.hal
