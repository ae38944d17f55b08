#!/bin/sh
# mkversion.sh OUT OBJ...: write a linker version script that keeps a realtime
# module's entry points, parameter metadata and EXPORT_SYMBOL()ed names global.
set -eu
out=$1; shift
tmp=$out.tmp
{
    echo "{ global: rtapi_app_main; rtapi_app_exit; rtapi_info_*; rtapi_export_*;"
    for o in "$@"; do
        objcopy -O binary -j .rtapi_export "$o" /dev/stdout 2>/dev/null | tr '\0' '\n'
    done | sed -n 's/^\([A-Za-z_][A-Za-z0-9_]*\)$/    \1;/p' | sort -u
    echo "  local: *; };"
} > "$tmp"
mv "$tmp" "$out"
