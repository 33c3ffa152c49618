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
cd build && ctest --output-on-failure "$@"
