# Sourced by bench scripts after `cd` to the tree's root: PoCL's CPU device
# with 2 compute units unless the environment says otherwise, the scene
# suite written, and $work, a folder removed at exit.
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/suite/make_suite.py >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The suite scenes that have a reference (out/suite/NAME/reference.pfm, from
# bench/suite.sh), one line each: name, file, and the scene's --ambient
# option if it has one; the others are named on stderr, after "$1: ".
suite_with_references() {
    grep -v '^#' scenes/suite/suite.txt | while read -r name file extra; do
        [ -n "$name" ] || continue
        if [ ! -f "out/suite/$name/reference.pfm" ]; then
            echo "$1: $name has no reference (out/suite/$name/reference.pfm): run bench/suite.sh" >&2
            continue
        fi
        echo "$name $file $(echo "$extra" | grep -o -- '--ambient [0-9. ]*' || true)"
    done
}
