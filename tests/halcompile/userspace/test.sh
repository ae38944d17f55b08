#!/bin/bash
# Userspace comp: build it with --compile, run it under halrun with count= and an extra argument, and with
# names= (split into the names[] array, empty names skipped, at most 16).
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp ucomp.comp ucomp.hal ucomp-names.hal "$tmp/"
cd "$tmp"
halcompile --preprocess ucomp.comp
grep -c '^int main(int argc, char \*\*argv)' ucomp.c
halcompile --compile ucomp.comp
test -x ucomp && echo "executable built next to the source"
PATH=$tmp:$PATH halrun -f ucomp.hal | sed 's/^ *[0-9]* /OWNER /'
PATH=$tmp:$PATH halrun -f ucomp-names.hal | sed 's/^ *[0-9]* /OWNER /'
./ucomp names="$(seq -s, 1 17)" 2>&1 || echo "exit $?"
./ucomp count=1 names=x 2>&1 || echo "exit $?"
