#!/bin/bash
# load-errors: hal_parport refuses bad cfg strings and ports it cannot claim with a clear message,
# and leaves no component behind.
log=$(mktemp)
trap 'realtime stop > /dev/null 2>&1; rm -f "$log"' EXIT
realtime start > "$log" 2>&1 || exit 1
seen=$(wc -l < "$log")
for cfg in "" "   " "0x378 zz" "parportx out" "0 1 2 3 4 5 6 7 8" "3" "/dev/nonexistent-parport" "/dev/null in"; do
    echo "== cfg=\"$cfg\""
    halcmd loadrt hal_parport cfg="$cfg" > /dev/null 2>&1
    echo "status $?"
    tail -n +$((seen + 1)) "$log"
    seen=$(wc -l < "$log")
done
echo "components: [$(halcmd list comp hal_parport)]"
