#!/bin/bash
# bad-input: long lines stay whole (a command hidden in a long comment never runs), endless lines
# end the file, NUL bytes, directories and missing files given to source or -f, and loadusr
# without a program.
cd "$(dirname "$0")"
realtime start 2> /dev/null || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"; realtime stop' EXIT
pad=$(printf '%03000d' 0)
echo "> a 3000-byte comment ending in a command"
printf '# %s newsig hidden bit\nnewsig shown bit\n' "$pad" > "$work/long-comment.hal"
halcmd -f "$work/long-comment.hal" 2>&1; echo "exit $?"
halcmd list sig
echo "> a 3000-byte command"
printf 'newsig %s bit\n' "$pad" > "$work/long-cmd.hal"
halcmd -f "$work/long-cmd.hal" 2>&1 | sed "s|$work/||"; echo "exit ${PIPESTATUS[0]}"
echo "> a line longer than 1 MiB"
head -c 1100000 /dev/zero | tr '\0' '#' > "$work/huge.hal"
printf '\nnewsig after_huge bit\n' >> "$work/huge.hal"
halcmd -f "$work/huge.hal" 2>&1 | sed "s|$work/||"; echo "exit ${PIPESTATUS[0]}"
echo "> an endless line (/dev/zero), also with -k"
timeout 30 halcmd -f /dev/zero 2>&1; echo "exit $?"
timeout 30 halcmd -k -f /dev/zero 2>&1; echo "exit $?"
echo "> a NUL byte"
printf 'newsig a bit\000newsig b bit\nnewsig c bit\n' > "$work/nul.hal"
halcmd -f "$work/nul.hal" 2>&1 | sed "s|$work/||"; echo "exit ${PIPESTATUS[0]}"
halcmd -k -f "$work/nul.hal" 2>&1 | sed "s|$work/||"; echo "exit ${PIPESTATUS[0]}"
halcmd list sig
echo "> source of a directory, of a missing file, -f of a directory"
printf 'newsig first bit\nsource %s\n' "$work" > "$work/srcdir.hal"
halcmd -f "$work/srcdir.hal" 2>&1 | sed "s|$work|WORK|g"; echo "exit ${PIPESTATUS[0]}"
printf '\nsource no-such.hal\n' > "$work/srcmissing.hal"
halcmd -f "$work/srcmissing.hal" 2>&1 | sed "s|$work/||"; echo "exit ${PIPESTATUS[0]}"
halcmd -f "$work" 2>&1 | sed "s|$work|WORK|g"; echo "exit ${PIPESTATUS[0]}"
echo "> loadusr without a program, with a bad option"
halcmd loadusr 2>&1; echo "exit $?"
halcmd loadusr -W 2>&1; echo "exit $?"
halcmd loadusr -n 2>&1; echo "exit $?"
halcmd loadusr -x true 2>&1; echo "exit $?"
