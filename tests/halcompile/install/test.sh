#!/bin/bash
# halcompile --install: into $USER_MODULE_DIR when set, else into rtlib/ of the run-in-place tree.
set -e
tmp=$(mktemp -d)
so=$EMC2_HOME/rtlib/hc_install_probe.so
trap 'rm -rf "$tmp" "$so"' EXIT
cp hc_install_probe.comp probe.hal script "$tmp/"
cd "$tmp"
mkdir mods
USER_MODULE_DIR=$tmp/mods halcompile --install hc_install_probe.comp
ls mods
RTLIB_DIR=$tmp/mods "$EMC2_HOME/objects/unit/comptest" < script
env -u USER_MODULE_DIR halcompile --install hc_install_probe.comp
test -f "$so" && echo "installed into rtlib"
halrun -f probe.hal | sed 's/^ *[0-9]* /OWNER /'
