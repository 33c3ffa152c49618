#!/bin/sh
# Sets up (Debian packages), builds, and renders the default scene.
set -eu
cd "$(dirname "$0")/.."
./tools/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >/dev/null
./build/vct render scenes/cornell_box.gltf -o out/cornell_box.png --stats
echo "image: $(pwd)/out/cornell_box.png"
