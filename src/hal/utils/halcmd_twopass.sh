#!/bin/bash
# halcmd_twopass [halcmd options] file.ini: run the INI file's [HAL]HALFILEs in two passes
# (lib/tcl/twopass.tcl under haltcl) from the INI file's directory, as the linuxcnc launcher does.
BINDIR=$(cd "$(dirname "$(readlink -f "$0")")" && pwd)
TOP=$(dirname "$BINDIR")

if [ "${1:-}" = --help ] || [ "${1:-}" = -h ]; then
    echo "Usage: halcmd_twopass [halcmd options] file.ini"
    echo "Runs the [HAL]HALFILE files of file.ini in two passes as [HAL]TWOPASS asks: every"
    echo "loadrt/loadusr first (repeated loads of a module merged), then the other commands."
    exit 0
fi
if [ $# -eq 0 ] || [ "${!#:0:1}" = "-" ]; then
    echo "Usage: halcmd_twopass [halcmd options] file.ini" >&2
    exit 1
fi
INI=${!#}
if [ ! -r "$INI" ]; then
    echo "halcmd_twopass: cannot read INI file '$INI'" >&2
    exit 1
fi
TWOPASS=$("$BINDIR/inivar" -ini "$INI" -var TWOPASS -sec HAL 2>/dev/null)
if [ -z "$TWOPASS" ]; then
    echo "halrun: An INI file may only be used if it specifies [HAL]TWOPASS" >&2
    exit 1
fi
INI=$(cd "$(dirname "$INI")" && pwd)/$(basename "$INI")
export HALLIB_DIR=${HALLIB_DIR:-$TOP/lib/hallib}
export PATH="$BINDIR:$PATH"
cd "$(dirname "$INI")" || exit 1
exec "$BINDIR/haltcl" -i "$INI" "$TOP/lib/tcl/twopass.tcl"
