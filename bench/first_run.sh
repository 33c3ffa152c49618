#!/bin/sh
# The first hour's figures: the quick start's render on a cold kernel cache
# (vct's and PoCL's emptied) and on a warm one, and the whole test suite's
# time, written to doc/results/first_run.md and the README's quick start, and
# the README's picture (the quick start's image).
# Run after ./tools/quickstart.sh has built vct.
# usage: bench/first_run.sh [--no-tests]
set -eu
cd "$(dirname "$0")/.."
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
cold=$(mktemp -d)
trap 'rm -rf "$cold"' EXIT
render() { # cache dirs -> wall seconds of the quick start's render
    start=$(date +%s.%N)
    VCT_CACHE_DIR="$1/vct" POCL_CACHE_DIR="$1/pocl" \
        ./build/vct render scenes/cornell_box.gltf -o out/cornell_box.png --stats >"$1.log" 2>&1
    awk "BEGIN { print $(date +%s.%N) - $start }"
}
cold_s=$(render "$cold")
warm_s=$(render "$cold")
cp out/cornell_box.png doc/cornell_box.png # the README's picture
programs=$(grep "kernel programs" "$cold.log" | sed 's/kernel programs: //')
tests_s=""
if [ "${1:-}" != "--no-tests" ]; then
    start=$(date +%s.%N)
    ./tools/test.sh -j2 >out/first_run_tests.log 2>&1
    tests_s=$(awk "BEGIN { print $(date +%s.%N) - $start }")
    summary=$(grep "tests passed" out/first_run_tests.log)
fi
stamp=$(bench/stamp.sh bench/first_run.sh "$@")
ratio=$(awk "BEGIN { printf \"%.1f\", $cold_s / $warm_s }")
mkdir -p doc/results
{
    echo "# The first run: kernel compilation and the test suite"
    echo
    echo "$stamp"
    echo
    echo "| what | seconds |"
    echo "|---|---:|"
    printf '| the quick start'"'"'s render, cold kernel cache (%s) | %.1f |\n' "$programs" "$cold_s"
    printf '| the same render, warm cache | %.1f |\n' "$warm_s"
    [ -z "$tests_s" ] || printf '| `./tools/test.sh -j2` (%s) | %.0f |\n' "$summary" "$tests_s"
    echo
    echo "The cold render is ${ratio}x the warm one. A cold cache compiles every kernel program the"
    echo "render needs, once per device and variant; PoCL builds one program at a time per process."
} > doc/results/first_run.md
{
    echo "$stamp"
    echo
    printf 'The first render compiles its kernels (%.0f s here, on a cold cache), a warm one takes\n' "$cold_s"
    printf '%.1f s; the test suite takes %s s.\n' "$warm_s" "$(printf '%.0f' "${tests_s:-0}")"
} | tools/python.sh bench/update_block.py README.md first-run
cat doc/results/first_run.md
