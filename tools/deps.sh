#!/bin/sh
# Installs the Debian 12 packages vct builds, tests and benchmarks with.
# Run as root; does nothing for packages already installed.
set -eu
PACKAGES="build-essential cmake pkg-config ocl-icd-opencl-dev opencl-c-headers pocl-opencl-icd
clinfo libcglm-dev libassimp-dev libcjson-dev libstb-dev libembree-dev python3 gnuplot-nox
python3-openvdb python3-numpy python3-pyopencl python3-pip libglfw3-dev libxrandr-dev libepoxy-dev xvfb xauth libgl1-mesa-dri"
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
# Mitsuba 3, the independent path tracer test_independent compares with, is
# not packaged by Debian: PyPI's wheel (the test is skipped without it).
if ! python3 -c "import mitsuba" 2>/dev/null; then
    echo "installing: mitsuba (PyPI)"
    python3 -m pip install -q --break-system-packages mitsuba ||
        echo "deps: pip could not install mitsuba; test_independent will be skipped" >&2
fi
