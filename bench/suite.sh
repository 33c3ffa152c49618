#!/bin/sh
# The scene suite against converged path-traced references: writes the suite
# (scenes/suite/make_suite.py), then runs bench/accuracy --quick on each scene
# (the ray caster, the path tracer from 1 spp up, cone tracing at its default
# and with sparse diffuse, photon mapping progressive, fixed and with final
# gathering, each against a 2048-spp reference of another seed,
# or what suite.txt gives the scene),
# and gathers one table: out/suite/table.md. References stay under out/suite.
# usage: bench/suite.sh [SIZE] [REFERENCE_SPP]   (default 128 2048)
set -eu
cd "$(dirname "$0")/.."
SIZE=${1:-128}
REF_SPP=${2:-2048}
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/suite/make_suite.py >/dev/null
mkdir -p out/suite
grep -v '^#' scenes/suite/suite.txt | while read -r name file extra; do
    [ -n "$name" ] || continue
    out=out/suite/$name
    mkdir -p "$out"
    ref=""
    [ -f "$out/reference.pfm" ] && ref="--reference $out/reference.pfm"
    echo "== $name" >&2
    # shellcheck disable=SC2086
    ./build/bench/accuracy "scenes/suite/$file" --quick --size "$SIZE" "$SIZE" \
        --reference-spp "$REF_SPP" --max-spp 1024 --pm --out "$out" $ref $extra >/dev/null ||
        echo "suite: $name failed; the table goes on without it" >&2
done
tools/python.sh bench/suite_table.py out/suite scenes/suite/suite.txt > out/suite/table.md
cat out/suite/table.md
