#!/bin/bash
# plain-make: `make` in an unconfigured tree configures it and builds; a second `make` does not
# configure again; a newer configure.ac reconfigures keeping the options (config.status
# --recheck); `make clean` never configures; a failing configure says what to do; `make check`
# installs the packages before it configures (its own set-up step).
# The real Makefile runs on a tiny tree, with autoreconf and configure replaced by stubs.
set -e
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$EMC2_HOME/Makefile" "$EMC2_HOME/Makefile.inc.in" "$EMC2_HOME/configure.ac" "$work/"
cp -r "$EMC2_HOME/build" "$work/build"
mkdir -p "$work/src/demo" "$work/stubs"
printf '#!/bin/sh\necho hello\n' > "$work/src/demo/hello.sh"
printf '$(call script,src/demo/hello.sh,bin/hello)\n' > "$work/src/demo/Submakefile"
# autoreconf stub: writes a configure that records its options in Makefile.inc and writes a
# config.status that can recheck (rerun configure with the same options)
cat > "$work/stubs/autoreconf" <<'STUB'
#!/bin/sh
echo "stub: autoreconf $*" >> log
cat > configure <<'CONF'
#!/bin/sh
echo "stub: configure $*" >> log
[ -n "$FAIL_CONFIGURE" ] && exit 1
printf 'CC = gcc\nCXX = g++\nCONFIGURED = yes\nOPTIONS = %s\n' "$*" > Makefile.inc
printf '#!/bin/sh\necho "stub: config.status $*" >> log\n[ "$1" = --recheck ] && exec ./configure %s\nexit 0\n' "$*" > config.status
chmod +x config.status
CONF
chmod +x configure
STUB
chmod +x "$work/stubs/autoreconf"
cd "$work"
export PATH=$work/stubs:$PATH
m() { make --no-print-directory "$@" > out 2>&1; echo "make $* -> $?"; grep -E '^Makefile:' out || true; }
echo "> fresh tree"
m
cat log; : > log
echo "built: $(bin/hello)"
echo "> again"
m
cat log
echo "> configured with an option, then configure.ac changes"
./configure --enable-asan
: > log
sleep 1; touch configure.ac
m
cat log; : > log
grep OPTIONS Makefile.inc
echo "> clean and distclean of an unconfigured tree"
make --no-print-directory distclean > /dev/null 2>&1
m clean
cat log
echo "> make check in an unconfigured tree"
mkdir -p scripts
printf '#!/bin/sh\necho "stub: install-deps" >> log\n' > scripts/install-deps
printf '#!/bin/sh\necho "stub: runtests $*" >> log\n' > scripts/runtests
chmod +x scripts/install-deps scripts/runtests
make --no-print-directory distclean > /dev/null 2>&1; : > log
m check
cat log; : > log
make --no-print-directory distclean > /dev/null 2>&1
echo "> configure fails"
FAIL_CONFIGURE=1 m || true
cat log
