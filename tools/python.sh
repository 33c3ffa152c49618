#!/bin/sh
# The Python interpreter every test and bench script runs: Debian's, for
# which tools/deps.sh installs every module they import (numpy, PyOpenCL and
# OpenVDB from Debian, Mitsuba 3 and OpenEXR from PyPI), whatever `python3`
# comes first on the PATH. $VCT_PYTHON overrides it.
# Usage: python.sh SCRIPT ARGS...   or   python.sh --path
PYTHON=${VCT_PYTHON:-/usr/bin/python3}
if [ "${1:-}" = "--path" ]; then
    echo "$PYTHON"
    exit 0
fi
exec "$PYTHON" "$@"
