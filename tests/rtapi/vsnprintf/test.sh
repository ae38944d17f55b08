#!/bin/bash
# rtapi_vsnprintf.h (installed in include/): a C program that includes it gets rtapi_vsnprintf(); every output
# is compared with the C library's (floating point with its %a).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
gcc -std=gnu11 -Wall -Werror -DULAPI -I"$EMC2_HOME/include" -o "$work/t" vsnprintf_test.c -lm || exit 1
g++ -x c++ -Wall -DULAPI -I"$EMC2_HOME/include" -o "$work/tcc" vsnprintf_test.c -lm || exit 1
"$work/t" && "$work/tcc" > /dev/null
