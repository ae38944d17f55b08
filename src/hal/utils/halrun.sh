#!/bin/bash
# halrun: run a HAL file (or interactive halcmd) in a fresh realtime session, then clean up.

BINDIR=$(cd "$(dirname "$(readlink -f "$0")")" && pwd)
export PATH="$BINDIR:$PATH"
export HAL_RTMOD_DIR="${HAL_RTMOD_DIR:-$(cd "$BINDIR/../rtlib" 2> /dev/null && pwd)}"

# Print the usage text.
usage() {
    cat <<'TXT'
Usage:
  halrun [-I] [halcmd_opts] [filename[.hal|.tcl|.ini]]
  halrun -T [halcmd_opts] [filename[.hal|.tcl|.ini]]
  halrun -U

  -I       run an interactive halcmd after the file
  -T       run haltcl (Tcl with a 'hal' command) instead of halcmd
  -U       force realtime to stop and unload everything
  -f file  the file to run
  -i ini   INI file for [SECTION]KEY substitution
  -e -k -q -s -v -R -Q -V  passed to halcmd
  -h       this help
TXT
}

HALCMD_OPTS=() FILE= INIFILE= INTERACTIVE=0 TCL=0 UNLOAD=0
[ "${1:-}" = --help ] && { usage; exit 0; }
while getopts ":ef:hi:kqsvIRQTUV" opt; do
    case "$opt" in
    e|k|q|s|v|R|Q|V) HALCMD_OPTS+=("-$opt") ;;
    f) FILE=$OPTARG ;;
    i) INIFILE=$OPTARG ;;
    I) INTERACTIVE=1 ;;
    T) TCL=1 ;;
    U) UNLOAD=1 ;;
    h) usage; exit 0 ;;
    *) printf 'halrun: illegal option -- %s\n\nFor usage try: halrun -h\n' "$OPTARG" >&2
       exit 1 ;;
    esac
done
shift $((OPTIND - 1))

if [ $# -gt 1 ]; then
    echo "halrun: too many arguments <$*>" >&2
    exit 1
fi
if [ $# -eq 1 ]; then
    if [ -n "$FILE" ]; then
        echo "halrun: Error: Specified '-f $1' and also <$FILE>" >&2
        exit 1
    fi
    FILE=$1
fi

if [ "$UNLOAD" = 1 ]; then
    halcmd -R
    halcmd stop
    halcmd unload all
    realtime stop
    exit 0
fi

if realtime status > /dev/null 2>&1; then
    echo "halrun: Realtime already running.  Use 'halrun -U' to stop existing realtime session." >&2
    exit 1
fi

case "$FILE" in
'') ;;
*.hal|*.tcl|*.ini) ;;
*) echo "halrun: Unknown file extension for filename=$FILE"; exit 1 ;;
esac

realtime start || exit $?

STATUS=0
# Remember the status of a failed step.
note() { local s=$?; [ $s -ne 0 ] && STATUS=$s; return 0; }

INIOPT=()
[ -n "$INIFILE" ] && INIOPT=(-i "$INIFILE")
case "$FILE" in
*.hal)
    halcmd "${HALCMD_OPTS[@]}" "${INIOPT[@]}" -f "$FILE"; note ;;
*.ini)
    halcmd_twopass "${HALCMD_OPTS[@]}" "$FILE"; note ;;
*.tcl)
    haltcl "${INIOPT[@]}" "$FILE"; note ;;
'')
    if [ "$TCL" = 1 ]; then
        haltcl "${INIOPT[@]}"; note
    else
        halcmd "${HALCMD_OPTS[@]}" -kf "${INIOPT[@]}"; note
    fi ;;
esac
if [ "$INTERACTIVE" = 1 ] && [ -n "$FILE" ]; then
    halcmd "${HALCMD_OPTS[@]}" -kf "${INIOPT[@]}"; note
fi

halcmd stop; note
halcmd unload all; note
realtime stop; note
exit $STATUS
