#!/bin/bash
# Build the rs274 libFuzzer harness (clang, ASan+UBSan) and run it for FUZZ_SECONDS (default 60).
set -e
cd "$(dirname "$0")"
TOP=$(cd ../../.. && pwd)
OUT=${FUZZ_OUT:-$TOP/objects/fuzz/rs274}
mkdir -p "$OUT/corpus"
SRCS=$(ls "$TOP"/src/emc/rs274ngc/*.cc "$TOP"/src/emc/rs274ngc/cycles/*.cc \
          "$TOP"/src/emc/rs274ngc/cutcomp/*.cc 2>/dev/null | grep -v '/rs274\.cc$' || true)
make -C "$TOP" -s lib/liblinuxcncini.so
clang++ -std=gnu++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$TOP/src" -I"$TOP/src/emc/ini" -DULAPI fuzz_rs274.cc $SRCS \
    -L"$TOP/lib" -llinuxcncini -Wl,-rpath,"$TOP/lib" -o "$OUT/fuzz_rs274"
cp -n seeds/*.ngc "$OUT/corpus/" 2>/dev/null || true
cp -n "$TOP"/tests/interp/*/*.ngc "$OUT/corpus/" 2>/dev/null || true
cd "$OUT"
exec ./fuzz_rs274 -max_total_time="${FUZZ_SECONDS:-60}" -max_len=4096 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 corpus
