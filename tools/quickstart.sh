#!/bin/sh
# Sets up (Debian packages), builds, and renders the default scene, saying
# how long each step took.
set -eu
cd "$(dirname "$0")/.."
now() { date +%s.%N; }
since() { awk "BEGIN { printf \"%.1f\", $(now) - $1 }"; }
./tools/deps.sh
start=$(now)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
echo "quickstart: build $(since "$start") s"
start=$(now)
./build/vct render scenes/cornell_box.gltf -o out/cornell_box.png --stats
echo "quickstart: render $(since "$start") s (the first render on a device compiles its kernels)"
echo "image: $(pwd)/out/cornell_box.png"
