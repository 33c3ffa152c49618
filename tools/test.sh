#!/bin/sh
# Builds vct and runs the whole test suite on PoCL's CPU device limited to
# 2 compute units (the configuration CI uses).
set -eu
cd "$(dirname "$0")/.."
./tools/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
export VCT_DEVICE="Portable Computing Language"
export POCL_MAX_PTHREAD_COUNT=2 POCL_CPU_MAX_CU_COUNT=2
# every kernel whose arguments a test checked is logged (program/arg_check.c)
export VCT_ARG_LOG="$PWD/build/kernels_checked.log"
rm -f "$VCT_ARG_LOG"
cd build && ctest --output-on-failure "$@"
# After the whole suite (no test chosen): every kernel the sources define
# was bound, and so checked, by some test.
case " $* " in
*" -R"* | *" -E"* | *" -L"* | *" -I"*) ;;
*) python3 ../tools/arg_coverage.py . "$VCT_ARG_LOG" ;;
esac
