#!/bin/sh
# Installs what vct builds, tests and benchmarks with: Debian 12 packages, and
# the Python modules the tests and benches import, for the one interpreter
# they all run (tools/python.sh: Debian's /usr/bin/python3, whose PyOpenCL
# and OpenVDB come from Debian). Run as root; installs only what is missing.
set -eu
cd "$(dirname "$0")/.."
PACKAGES="build-essential cmake pkg-config ocl-icd-opencl-dev opencl-c-headers pocl-opencl-icd
clinfo libcglm-dev libassimp-dev libcjson-dev libxxhash-dev libb64-dev libopenmpi-dev openmpi-bin libstb-dev libembree-dev libopenexr-dev gnuplot-nox
python3 python3-pip python3-numpy python3-pil python3-pyopencl python3-openvdb
libglfw3-dev libxrandr-dev libepoxy-dev xvfb xauth libgl1-mesa-dri"
missing=""
for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "deps: installing Debian packages:$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
# Not packaged by Debian, from PyPI: Mitsuba 3 (the independent renderer
# test_independent compares with) and OpenEXR's own Python bindings (which
# read back the EXR files vct writes).
PYTHON=$(./tools/python.sh --path)
"$PYTHON" - <<'PY' || {
import importlib.util, sys
sys.exit(0 if all(importlib.util.find_spec(m) for m in ("mitsuba", "OpenEXR")) else 1)
PY
    echo "deps: installing Python modules for $PYTHON: mitsuba OpenEXR"
    "$PYTHON" -m pip install -q --disable-pip-version-check --break-system-packages \
        mitsuba OpenEXR
}
