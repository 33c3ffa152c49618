# shellcheck shell=sh
# Sourced by bench scripts after `cd` to the tree's root: PyPI's pyoidn
# (Intel Open Image Denoise) for the interpreter the benches run, installed
# once; where it cannot be had, the OIDN figures are left out with a message.
"$(tools/python.sh --path)" -c "import pyoidn" 2>/dev/null ||
    "$(tools/python.sh --path)" -m pip install -q --disable-pip-version-check \
        --break-system-packages pyoidn ||
    echo "pyoidn cannot be installed: the OIDN figures are left out" >&2
