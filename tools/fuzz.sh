#!/bin/sh
# Fuzzes scene loading and validation (OBJ+MTL, glTF with its buffers, binary
# glTF) with libFuzzer and AddressSanitizer/LeakSanitizer (leaks inside assimp
# itself suppressed: tools/fuzz/lsan.supp), seeded with the scene suite and
# the Cornell box, for SECONDS (default 3600) on JOBS processes (default 1).
# Crashes, leaks and hangs land in out/fuzz/ as crash-*, leak-*, timeout-*;
# each one fixed is kept in tests/load/inputs/, which test_scene_inputs
# loads on every test run.
# usage: tools/fuzz.sh [SECONDS] [JOBS]
set -eu
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${1:-3600}
JOBS=${2:-1}
command -v clang >/dev/null || { echo "fuzz: needs clang (apt-get install clang)"; exit 2; }
CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVCT_FUZZ=ON \
    -DVCT_BUILD_TESTS=OFF -DVCT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene_load >/dev/null
tools/python.sh scenes/suite/make_suite.py >/dev/null
mkdir -p out/fuzz/corpus out/fuzz/seeds
# seeds: the format byte (0 glTF, 1 binary glTF, 2 OBJ, NUL, MTL), then the file
for f in scenes/suite/*.gltf scenes/cornell_box.gltf; do
    n=$(basename "$f" .gltf)
    [ "$(wc -c <"$f")" -lt 400000 ] || continue  # libFuzzer's inputs stay small
    { printf '\000'; cat "$f"; } >"out/fuzz/seeds/$n.in"
done
{ printf '\002'; cat scenes/cornell_box.obj; printf '\000'; cat scenes/cornell_box.mtl; } \
    >out/fuzz/seeds/cornell_obj.in
for f in tests/load/inputs/*.gltf tests/load/inputs/*.glb tests/load/inputs/*.obj; do
    case $f in *.gltf) b='\000' ;; *.glb) b='\001' ;; *) b='\002' ;; esac
    { printf "$b"; cat "$f"; } >"out/fuzz/seeds/$(basename "$f").in"
done
cd out/fuzz
# fork mode keeps fuzzing past a finding, so that one run collects them all
# leaks inside assimp itself are upstream: tools/fuzz/lsan.supp (the full
# stacks of malloc, so that the suppression sees assimp in them)
LSAN_OPTIONS=suppressions=$(pwd)/../../tools/fuzz/lsan.supp:print_suppressions=1 \
ASAN_OPTIONS=detect_leaks=1:fast_unwind_on_malloc=0:allocator_may_return_null=1 \
    ../../build-fuzz/fuzz_scene_load corpus seeds -max_total_time="$SECONDS_TO_RUN" \
    -timeout=20 -rss_limit_mb=4096 -max_len=400000 -fork="$JOBS" -ignore_crashes=1 \
    -ignore_timeouts=1 -ignore_ooms=1 -print_final_stats=1 >fuzz.log 2>&1 || true
tail -n 5 fuzz.log
found=0
for f in crash-* leak-* timeout-* oom-*; do
    [ -e "$f" ] || continue
    echo "fuzz: found $f"
    found=1
done
[ $found -eq 0 ] || exit 1
echo "fuzz: no crash, leak or hang in ${SECONDS_TO_RUN} s"
