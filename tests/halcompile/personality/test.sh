#!/bin/bash
# personality: conditional pins, [MAX : EXPR] arrays, default_personality and load errors.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp pers.comp "$tmp/"
here=$PWD
cd "$tmp"
halcompile --compile pers.comp
for s in script1 script2 script3; do
    echo "== $s"
    RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest" < "$here/$s"
done
