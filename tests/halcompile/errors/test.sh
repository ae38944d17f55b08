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
try badarr <<'X'
component badarr;
pin out float out[3];
function _;
license "GPL";
;;
X
try twohash <<'X'
component twohash;
pin out float out-#-#[3];
function _;
license "GPL";
;;
X
try scalarhash <<'X'
component scalarhash;
pin out float out-#;
function _;
license "GPL";
;;
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
try dup <<'X'
component dup;
pin out float out;
param rw float out;
function _;
license "GPL";
;;
X
try reserved <<'X'
component reserved;
pin out float comp_id;
function _;
license "GPL";
;;
X
try nopins <<'X'
component nopins;
param rw float x;
function _;
license "GPL";
;;
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
try userfunct <<'X'
component userfunct;
pin out float out;
function _;
option userspace yes;
license "GPL";
;;
X
try dupoption <<'X'
component dupoption;
pin out float out;
option singleton yes;
option singleton no;
function _;
license "GPL";
;;
X
try baddir <<'X'
component baddir;
pin sideways float out;
function _;
license "GPL";
;;
X
try badtype <<'X'
component badtype;
pin in complex z;
function _;
license "GPL";
;;
X
try unterminated <<'X'
component unterminated;
pin in float x "no end
;;
X
try missingsemi <<'X'
component missingsemi;
pin in float x
function _;
license "GPL";
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
echo "== -o with --compile"
halcompile --compile -o x.c fpwarn.comp 2>&1; echo "exit $?"
echo "== -o with two inputs"
halcompile -o x.c fpwarn.comp userinit.comp 2>&1; echo "exit $?"
echo "== preprocess of a .c file"
echo "int x;" > plain.c
halcompile plain.c 2>&1; echo "exit $?"
echo "== unknown option"
halcompile --bogus 2>/dev/null | head -1; echo "exit ${PIPESTATUS[0]}"
echo "== help"
halcompile --help | head -1; echo "exit ${PIPESTATUS[0]}"
echo "== missing file"
halcompile nosuch.comp 2>&1; echo "exit $?"
echo "== bad personality count"
halcompile -P x fpwarn.comp 2>&1; echo "exit $?"
echo "== array size that is not an integer"
printf 'component badsize;\npin out float out-#[2.5];\nfunction _;\nlicense "GPL";\n;;\n' > badsize.comp
halcompile badsize.comp 2>&1; echo "exit $?"
