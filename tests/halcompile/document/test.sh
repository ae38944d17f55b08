#!/bin/bash
# --document writes a man page (section 9 for realtime comps) next to the input or to -o FILE.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp kinds.comp "$tmp/"
cd "$tmp"
halcompile --document kinds.comp
cat kinds.9
halcompile --document -o other/kinds.9 kinds.comp 2>&1 || echo "missing directory: exit $?"
mkdir other
halcompile -d -o other/kinds.9 kinds.comp
cmp kinds.9 other/kinds.9 && echo "same page with -o"
