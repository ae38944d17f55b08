#!/bin/bash
# Every declaration kind: compile kinds.comp out of tree and drive the module with comptest.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp kinds.comp "$tmp/"
cd "$tmp"
halcompile --compile kinds.comp
RTLIB_DIR=$tmp "$EMC2_HOME/objects/unit/comptest" < "$OLDPWD/script"
