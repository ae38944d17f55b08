#!/bin/bash
# HAL file syntax: continuation, comments, quotes, $ENV, [INI] with -i, echo, print, quit, tokens.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
export SIGNAME=fromenv
halcmd -k -i syntax.ini -f syntax.hal 2>&1
echo "exit $?"
echo "> DOS line endings"
printf 'newsig dos bit\r\ngets dos\r\nnewsig e\rf bit\n' > dos.tmp.hal
halcmd -f dos.tmp.hal 2>&1
echo "exit $?"
rm -f dos.tmp.hal
echo "> -e echo"
printf 'print one # comment \n\nprint "two"\n' | halcmd -e -f 2>&1
echo "> missing ini"
echo 'gets [A]B' | halcmd -f 2>&1
echo "exit $?"
realtime stop
