#!/bin/bash
# Userspace comp: build it with --compile, run it under halrun with count= and an extra argument.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp ucomp.comp ucomp.hal "$tmp/"
cd "$tmp"
halcompile --preprocess ucomp.comp
grep -c '^int main(int argc, char \*\*argv)' ucomp.c
halcompile --compile ucomp.comp
test -x ucomp && echo "executable built next to the source"
PATH=$tmp:$PATH halrun -f ucomp.hal | sed 's/^ *[0-9]* /OWNER /'
