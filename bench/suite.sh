#!/bin/sh
# The scene suite against converged path-traced references: writes the suite
# (scenes/suite/make_suite.py), then runs bench/accuracy --quick on each scene
# (the ray caster, the path tracer from 1 spp up, cone tracing at its default
# and with dense diffuse, photon mapping progressive, fixed and with final
# gathering, each against an 8192-spp reference of another seed,
# or what suite.txt gives the scene; at 2048 spp the noisiest references
# held 6 % NRMSE of their own, which every method's error took in), and
# bench/denoised_rows.py on it (the path tracer at 1 to 1024 spp denoised by
# the engine's filter and by OIDN),
# and gathers one table: out/suite/table.md, the page doc/results/suite.md
# with the README's summary of it, and the error-time plot of every scene
# (bench/suite_plot.py, doc/results/suite_front.png). References stay under out/suite.
# Every row's time is each stage's fastest of REPEAT renders (default 3): one
# run on a shared CPU moves by a fifth.
# usage: bench/suite.sh [SIZE] [REFERENCE_SPP] [REPEAT]   (default 128 8192 3)
set -eu
cd "$(dirname "$0")/.."
SIZE=${1:-128}
REF_SPP=${2:-8192}
REPEAT=${3:-3}
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/suite/make_suite.py >/dev/null
# shellcheck source=bench/oidn_env.sh
. bench/oidn_env.sh
mkdir -p out/suite
grep -v '^#' scenes/suite/suite.txt | while read -r name file extra; do
    [ -n "$name" ] || continue
    out=out/suite/$name
    mkdir -p "$out"
    # a reference is kept while it has the samples asked for (reference.spp)
    spp=$(echo "$extra" | grep -o -- '--reference-spp [0-9]*' | awk '{ print $2 }')
    spp=${spp:-$REF_SPP}
    ref=""
    if [ -f "$out/reference.pfm" ] && [ "$(cat "$out/reference.spp" 2>/dev/null)" = "$spp" ]; then
        ref="--reference $out/reference.pfm"
    else
        rm -f "$out/reference.pfm" "$out/reference.spp"
    fi
    echo "== $name" >&2
    # shellcheck disable=SC2086
    ./build/bench/accuracy "scenes/suite/$file" --quick --size "$SIZE" "$SIZE" \
        --reference-spp "$REF_SPP" --max-spp 1024 --pm --repeat "$REPEAT" --out "$out" $ref $extra >/dev/null ||
        echo "suite: $name failed; the table goes on without it" >&2
    [ -n "$ref" ] || [ ! -f "$out/reference.pfm" ] || echo "$spp" >"$out/reference.spp"
    # the path tracer denoised by the engine's filter and by OIDN
    ambient=$(echo "$extra" | grep -o -- '--ambient [0-9. ]*' || true)
    # shellcheck disable=SC2086
    tools/python.sh bench/denoised_rows.py --repeat "$REPEAT" ./build/vct "scenes/suite/$file" "$out/reference.pfm" \
        "$out" "$SIZE" $ambient || echo "suite: $name's denoised rows failed" >&2
done
tools/python.sh bench/suite_table.py out/suite scenes/suite/suite.txt > out/suite/table.md
tools/python.sh bench/suite_table.py out/suite scenes/suite/suite.txt --summary > out/suite/summary.md
mkdir -p doc/results
stamp=$(bench/stamp.sh bench/suite.sh "$@")
tools/python.sh bench/suite_plot.py out/suite scenes/suite/suite.txt doc/results/suite_front.png \
    "$(echo "$stamp" | tr -d '_`')" ||
    echo "suite: no plot (gnuplot?)" >&2
{
    echo "# The scene suite: error and time"
    echo
    echo "$stamp"
    echo
    echo "Each scene of \`scenes/suite/suite.txt\` at ${SIZE}x${SIZE}, against a path-traced reference of"
    echo "$REF_SPP samples per pixel (another seed; more or fewer where suite.txt says so: more"
    echo "where a scene's path tracer is noisiest, so that the reference's own noise, which every"
    echo "method's error takes in, stays near 2 %, fewer where it is slowest). NRMSE is the RMSE"
    echo "over all pixels and channels over the reference's mean; device ms is the sum of the"
    echo "stages' device time: the acceleration structure, the voxels and their light, and the"
    echo "image; for a denoised path tracer, the guides and the filter too (OIDN's: its filter"
    echo "call on the same CPU), each stage's fastest of $REPEAT renders (the image is the same"
    echo "bits each time; one run on a shared CPU moves by a fifth). The last columns are"
    echo "the time the path tracer needs for the same error, read between its sample counts (1 to"
    echo "1024 spp; denoised likewise): as it is, denoised by the engine's filter, and by OIDN."
    echo
    echo "![Error against time, every scene](suite_front.png)"
    echo
    echo "## Every method at its default, over the suite"
    echo
    cat out/suite/summary.md
    echo
    echo "## Every scene"
    echo
    cat out/suite/table.md
} > doc/results/suite.md
{
    echo "$stamp"
    echo
    cat out/suite/summary.md
} | tools/python.sh bench/update_block.py README.md suite-summary
cat out/suite/table.md
