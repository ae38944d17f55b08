# c-header: a C program compiled with -Wall -Wextra -Werror against include/inifile.h and linked to
# liblinuxcncini uses LinuxCNC's path-based iniFind* calls.
set -e
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# on a sanitizer build (configure --enable-asan) a program using the tree's libraries links the
# sanitizer runtimes too, as halcompile does
asan=$(sed -n 's/^ASAN_FLAGS *= *//p' "$EMC2_HOME/Makefile.inc")
# shellcheck disable=SC2086
gcc -O2 -Wall -Wextra -Werror $asan -I"$HEADERS" -DULAPI -L"$LIBDIR" -o "$work/lookup" lookup.c -llinuxcncini
# l TYPE KEY SECTION: one lookup with its exit status
l() { "$work/lookup" values.ini "$@" 2>&1 || echo "[exit $?]"; }
l s TEXT -
l s TEXT T
l s LONG S
l s NOPE -
l s TEXT NOSECTION
l i NEG S
l u NEG S
l n NEG S
l u BIG -
l r REAL -
l b FLAG -
l i BAD -
l r TEXT -
l b TEXT -
"$work/lookup" no-such.ini s TEXT - 2>&1 || echo "[exit $?]"
