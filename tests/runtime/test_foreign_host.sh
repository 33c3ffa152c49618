#!/bin/sh
# Runs foreign_host.py with the tests' Python (tools/python.sh), for which
# tools/deps.sh installs PyOpenCL and numpy.
# Usage: test_foreign_host.sh KERNEL_DIR FOREIGN_REF SCENE
exec "$(dirname "$0")/../../tools/python.sh" "$(dirname "$0")/foreign_host.py" "$@"
