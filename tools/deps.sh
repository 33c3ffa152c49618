#!/bin/sh
# Installs the Debian 12 packages vct builds, tests and benchmarks with.
# Run as root; does nothing for packages already installed.
set -eu
PACKAGES="build-essential cmake pkg-config ocl-icd-opencl-dev opencl-c-headers pocl-opencl-icd
clinfo libcglm-dev libassimp-dev libcjson-dev libstb-dev libembree-dev python3 gnuplot-nox
python3-openvdb python3-numpy python3-pyopencl libglfw3-dev libxrandr-dev libepoxy-dev xvfb xauth libgl1-mesa-dri"
missing=""
for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "installing:$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
