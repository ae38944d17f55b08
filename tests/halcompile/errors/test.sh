#!/bin/bash
# Error cases: each bad .comp must give its message and a non-zero exit status.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# try NAME ARGS...: run halcompile on NAME.comp (written from stdin), show status and messages
try() {
    local name=$1; shift
    cat > "$name.comp"
    echo "== $name"
    halcompile "$@" "$name.comp" 2>&1
    echo "exit $?"
    [ -e "$name.c" ] && echo "$name.c left behind"
    rm -f "$name.c"
}
# Plain components: "component NAME;", the declarations, "function _;", a license, no code.
# One line per case: NAME|declaration|declaration...
while IFS='|' read -ra f; do
    { echo "component ${f[0]};"; printf '%s\n' "${f[@]:1}" 'function _;' 'license "GPL";' ';;'; } |
        try "${f[0]}"
done <<'X'
badarr|pin out float out[3];
twohash|pin out float out-#-#[3];
scalarhash|pin out float out-#;
dup|pin out float out;|param rw float out;
reserved|pin out float comp_id;
nopins|param rw float x;
userfunct|pin out float out;|option userspace yes;
dupoption|pin out float out;|option singleton yes;|option singleton no;
baddir|pin sideways float out;
badtype|pin in complex z;
missingsemi|pin in float x
X
try mismatch <<'X'
component othername;
pin out float out;
function _;
license "GPL";
;;
X
try nolicense <<'X'
component nolicense;
pin out float out;
function _;
;;
out = 1;
X
try twofuncts <<'X'
component twofuncts;
pin out float out;
function a;
function b;
license "GPL";
;;
out = 1;
X
try unterminated <<'X'
component unterminated;
pin in float x "no end
;;
X
try fpwarn <<'X'
component fpwarn;
pin out float out;
function _ fp;
license "GPL";
;;
out = 1;
X
try userinit <<'X'
component userinit;
pin out float out;
function _;
option userinit yes;
license "GPL";
;;
out = 1;
X
# run TITLE COMMAND...: show the title, the command's messages and its exit status
run() {
    echo "== $1"; shift
    "$@" 2>&1
    echo "exit $?"
}
run "-o with --compile" halcompile --compile -o x.c fpwarn.comp
run "-o with two inputs" halcompile -o x.c fpwarn.comp userinit.comp
echo "int x;" > plain.c
run "preprocess of a .c file" halcompile plain.c
echo "== unknown option"
halcompile --bogus 2>/dev/null | head -1; echo "exit ${PIPESTATUS[0]}"
echo "== help"
halcompile --help | head -1; echo "exit ${PIPESTATUS[0]}"
run "missing file" halcompile nosuch.comp
run "bad personality count" halcompile -P x fpwarn.comp
printf 'component badsize;\npin out float out-#[2.5];\nfunction _;\nlicense "GPL";\n;;\n' > badsize.comp
run "array size that is not an integer" halcompile badsize.comp
