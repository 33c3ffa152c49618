#!/bin/sh
# Whitted ray tracing's adaptive subsampling against tracing every pixel:
# square sizes 4, 8 and 16, with the corners' keys alone (--contrast 0) and
# with the default contrast test, on three suite scenes at 320x240. Writes
# doc/results/subsample.md: the share of camera rays cast and the NRMSE
# against the full render.
# usage: bench/subsample.sh
set -eu
cd "$(dirname "$0")/.."
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
rows=$work/rows.md
for scene in scenes/cornell_box.gltf scenes/suite/glass_mirror_box.gltf scenes/suite/small_objects.gltf; do
    ./build/vct render "$scene" --method whitted --size 320 240 -o "$work/full.pfm" >/dev/null 2>&1
    for n in 4 8 16; do
        for c in 0 0.05; do
            share=$(./build/vct render "$scene" --method whitted --size 320 240 --subsample "$n" \
                --contrast "$c" -o "$work/sub.pfm" 2>&1 | sed -n 's/.*camera rays (\([0-9.]*\) %.*/\1/p')
            err=$(./build/vct compare "$work/sub.pfm" "$work/full.pfm" | sed -n 's/^nrmse //p')
            printf '| %s | %s | %s | %s %% | %.5f |\n' "$(basename "$scene" .gltf)" "$n" "$c" "$share" "$err" >>"$rows"
        done
    done
done
{
    echo "# Adaptive subsampling: rays against error"
    echo
    bench/stamp.sh bench/subsample.sh
    echo
    echo "Whitted ray tracing at 320x240 with \`--subsample N\`, against the same render tracing every"
    echo "pixel: the share of camera rays cast and the NRMSE. \`--contrast 0\` splits a square only where"
    echo "its corners' keys (materials along the ray tree, lights seen) differ; the default also"
    echo "splits where their radiance spreads by more than 0.05 of its mean."
    echo
    echo "| scene | N | contrast | camera rays | NRMSE against every pixel |"
    echo "|---|---:|---:|---:|---:|"
    cat "$rows"
} >doc/results/subsample.md
cat doc/results/subsample.md
