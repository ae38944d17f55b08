#!/bin/bash
# Unit test of halcmd line parsing (comments, quotes, $ENV, [INI], tokens) and value formats.
cd "$(dirname "$0")"
T="$EMC2_HOME/objects/unit/halcmd_parse_test"
"$T" < cases.txt 2>&1
printf 'line a b\r\nline c d\r\nline a\rb\n' | "$T" 2>&1
