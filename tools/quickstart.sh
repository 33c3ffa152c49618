#!/bin/sh
# Sets up (Debian packages), builds, compiles the kernels for this machine's
# device, and renders the default scene, saying how long each step took.
set -eu
cd "$(dirname "$0")/.."
now() { date +%s.%N; }
since() { awk "BEGIN { printf \"%.1f\", $(now) - $1 }"; }
./tools/deps.sh
start=$(now)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
echo "quickstart: build $(since "$start") s"
# kernels are compiled once per device and driver, here rather than in the
# first render (vct compile; a render compiles what it lacks itself)
start=$(now)
./build/vct compile scenes/cornell_box.gltf
echo "quickstart: kernels $(since "$start") s"
start=$(now)
./build/vct render scenes/cornell_box.gltf -o out/cornell_box.png --stats
echo "quickstart: render $(since "$start") s"
echo "image: $(pwd)/out/cornell_box.png"
