#!/usr/bin/env python3
"""Which kernels the test suite binds checked arguments to.

Usage: tools/arg_coverage.py BUILD_DIR [LOG]

Without LOG, runs the suite (ctest in BUILD_DIR, 2 jobs) with $VCT_ARG_LOG
set, so that every kernel whose arguments a test checked (VCT_CHECK_ARGS=1,
host/src/program/arg_check.c) is written to the log; with LOG, reads a log
written before. Lists the kernels the sources under kernels/ define that no
test bound, and exits non-zero when there are any."""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KERNEL = re.compile(r"(?:__kernel|\bkernel)\s+void\s+(\w+)\s*\(")


def defined():
    """{kernel name: the file that defines it}"""
    found = {}
    for top, _, files in os.walk(os.path.join(ROOT, "kernels")):
        for f in sorted(files):
            if f.endswith((".cl", ".h")):
                path = os.path.join(top, f)
                with open(path) as src:
                    for name in KERNEL.findall(src.read()):
                        found[name] = os.path.relpath(path, ROOT)
    return found


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    build = sys.argv[1]
    if len(sys.argv) == 3:
        log = sys.argv[2]
    else:
        log = os.path.join(tempfile.mkdtemp(prefix="vct-args-"), "checked.log")
        env = dict(os.environ, VCT_ARG_LOG=log)
        subprocess.run(["ctest", "--test-dir", build, "-j2", "--output-on-failure"], env=env,
                       check=True)
    with open(log) as f:
        checked = {line.strip() for line in f if line.strip()}
    kernels = defined()
    missing = sorted(k for k in kernels if k not in checked)
    print(f"arguments checked for {len(kernels) - len(missing)} of {len(kernels)} kernels")
    for k in missing:
        print(f"  never bound by a test: {k} ({kernels[k]})")
    sys.exit(1 if missing else 0)


if __name__ == "__main__":
    main()
