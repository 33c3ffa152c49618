#!/bin/sh
# Runs foreign_host.py with the first Python that has PyOpenCL (Debian's
# python3-pyopencl lives in /usr/bin/python3); skips, saying why, without one.
# Usage: test_foreign_host.sh KERNEL_DIR FOREIGN_REF SCENE
for py in /usr/bin/python3 python3; do
    if "$py" -c "import pyopencl, numpy" 2>/dev/null; then
        exec "$py" "$(dirname "$0")/foreign_host.py" "$@"
    fi
done
echo "test_foreign_host: skipped: no Python with pyopencl and numpy (apt install python3-pyopencl)"
exit 77
