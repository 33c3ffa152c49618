# Sourced by bench scripts after `cd` to the tree's root: PoCL's CPU device
# with 2 compute units unless the environment says otherwise, the scene
# suite written, and $work, a folder removed at exit.
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/suite/make_suite.py >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
