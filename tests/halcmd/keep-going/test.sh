#!/bin/bash
# -k keeps going after failures; without -k the first failure stops; exit status; later commands still work.
realtime start 2> /dev/null || exit 1
printf 'newsig a s32\nsets a x\nsets a 3\ngets a\n' > kg.tmp.hal
halcmd -f kg.tmp.hal 2>&1
echo "exit $?"
halcmd -k -f kg.tmp.hal 2>&1
echo "exit $?"
halcmd gets a 2>&1
echo "exit $?"
printf 'gets a\nquit\ngets nosuch\n' | halcmd -f 2>&1
echo "exit $?"
printf 'gets nosuch\nexit\n' | halcmd -k -f 2>&1
echo "exit $?"
rm -f kg.tmp.hal
realtime stop
