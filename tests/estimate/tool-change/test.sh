#!/bin/bash
# openemc-estimate plans M6's move to [EMCIO]TOOL_CHANGE_POSITION as the real run does: the same
# program takes more servo cycles in motion on the machine that has a tool change position.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp ../cycles/tool.tbl.in "$work/tool.tbl"
cp ../cycles/test.ini "$work/plain.ini"
sed 's/^TOOL_TABLE = tool.tbl$/&\nTOOL_CHANGE_POSITION = 0 0 20/' ../cycles/test.ini > "$work/change.ini"
printf 'G21 G90\nG0 X40 Y30 Z5\nT1 M6\nG0 X40 Y30\nM2\n' > "$work/change.ngc"
cycles() {
    openemc-estimate --quiet "$work/$1" "$work/change.ngc" |
        sed -n 's/^servo cycles: .* total, \([0-9]*\) in motion$/\1/p'
}
plain=$(cycles plain.ini)
change=$(cycles change.ini)
echo "without: $plain cycles, with: $change cycles" >&2
[ -n "$plain" ] && [ -n "$change" ] || { echo "no cycle count"; exit 1; }
[ "$change" -gt "$plain" ] && echo "tool change position moves" || echo "tool change position ignored"
