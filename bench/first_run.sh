#!/bin/sh
# A new user's first run, measured: a fresh clone of the committed tree, with
# empty kernel caches (vct's and PoCL's), runs the README's two commands,
# ./tools/quickstart.sh and ./tools/test.sh (the Debian packages and Python
# modules already installed: their download is not timed), then renders the
# quick start's image again on the warm cache, and once more on empty caches
# without `vct compile` (what a render costs on a device nothing compiled for). Writes doc/results/first_run.md,
# the README's quick-start figures and its picture (the quick start's image).
# usage: bench/first_run.sh
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$root" "$work/vct"
export VCT_CACHE_DIR="$work/cache/vct" POCL_CACHE_DIR="$work/cache/pocl"
seconds() { # command... -> its wall seconds; its output in $work/last.log
    start=$(date +%s.%N)
    "$@" >"$work/last.log" 2>&1 || { cat "$work/last.log" >&2; exit 1; }
    awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }"
}
cd "$work/vct"
quick_s=$(seconds ./tools/quickstart.sh)
cp "$work/last.log" "$work/quick.log"
first_s=$(awk '/^quickstart: render/ { print $3 }' "$work/quick.log")
build_s=$(awk '/^quickstart: build/ { print $3 }' "$work/quick.log")
compile_s=$(awk '/^quickstart: kernels/ { print $3 }' "$work/quick.log")
compiled=$(sed -n 's/^vct compile: \([0-9]*\) kernel programs compiled.*/\1/p' "$work/quick.log")
export VCT_DEVICE="Portable Computing Language"
warm_s=$(seconds ./build/vct render scenes/cornell_box.gltf -o out/cornell_box.png --stats)
rm -rf "$work/cache"
cold_s=$(seconds ./build/vct render scenes/cornell_box.gltf -o "$work/cold.png" --stats)
programs=$(sed -n 's/^kernel programs: //p' "$work/last.log")
tests_s=$(seconds ./tools/test.sh -j2)
summary=$(grep "tests passed" "$work/last.log")
cp out/cornell_box.png "$root/doc/cornell_box.png"
stamp=$(bench/stamp.sh bench/first_run.sh) # the clone's: the commit measured
cd "$root"
ratio=$(awk "BEGIN { printf \"%.1f\", $first_s / $warm_s }")
cold_ratio=$(awk "BEGIN { printf \"%.1f\", $cold_s / $warm_s }")
mkdir -p doc/results
{
    echo "# The first run: the two commands of the quick start"
    echo
    echo "$stamp"
    echo
    echo "A fresh clone, empty kernel caches, the packages already installed."
    echo
    echo "| what | seconds |"
    echo "|---|---:|"
    echo "| \`./tools/quickstart.sh\`, in all | $quick_s |"
    echo "| of which the build | $build_s |"
    echo "| of which \`vct compile\`: $compiled kernel programs, for every method | $compile_s |"
    echo "| of which the first render | $first_s |"
    echo "| the same render again | $warm_s |"
    echo "| the same render on empty kernel caches, without \`vct compile\` ($programs) | $cold_s |"
    echo "| \`./tools/test.sh -j2\` ($summary) | $tests_s |"
    echo
    echo "The quick start's first render takes ${ratio}x a warm one: \`vct compile\` has built the"
    echo "kernels before it, for this device and driver. Without it a render compiles what it needs"
    echo "itself, once, and takes ${cold_ratio}x: PoCL compiles one program at a time per process, and"
    echo "each kernel again for its work-group size at its first launch."
} >doc/results/first_run.md
{
    echo "$stamp"
    echo
    echo "On a fresh clone with the packages installed, the quick start takes $quick_s s: the build"
    echo "$build_s s, compiling the kernels for this device $compile_s s (\`vct compile\`, once per"
    echo "device and driver), the first render $first_s s (a later one $warm_s s). The test suite"
    echo "takes $tests_s s."
} | tools/python.sh bench/update_block.py README.md first-run
cat doc/results/first_run.md
