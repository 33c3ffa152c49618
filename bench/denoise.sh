#!/bin/sh
# The engine's denoiser against Intel Open Image Denoise on the scene suite:
# the path tracer at 4 and 16 spp, denoised by each, against the suite's
# references (bench/suite.sh renders them first); then photon mapping and
# cone tracing with and without the engine's filter. Writes
# doc/results/denoise.md. OIDN comes from PyPI's pyoidn, installed here; where
# it cannot be had, its columns say so.
# usage: bench/denoise.sh [SIZE]   (the suite's size, default 128)
set -eu
cd "$(dirname "$0")/.."
SIZE=${1:-128}
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
PY=$(tools/python.sh --path)
# shellcheck source=bench/oidn_env.sh
. bench/oidn_env.sh
mkdir -p out/denoise doc/results
rows=out/denoise/rows.md
others=out/denoise/others.md
: >"$rows"
: >"$others"
stage_ms() { # stats file, stage -> device ms
    awk -v s="$2" '$0 ~ "^"s" " { print $(NF - 3); exit }' "$1"
}
suite_with_references denoise | while read -r name file ambient; do
    ref=out/suite/$name/reference.pfm
    for spp in 4 16; do
        out=out/denoise/${name}_$spp
        # shellcheck disable=SC2086
        ./build/vct render "scenes/suite/$file" --method pt --spp "$spp" --seed 1 \
            --size "$SIZE" "$SIZE" --denoise --aov --exr float --stats $ambient \
            -o "$out.exr" >"$out.stats" 2>&1
        set -- $("$PY" bench/denoise_compare.py "$out.exr" "$ref")
        echo "| $name | $spp | $1 | $2 | $(stage_ms "$out.stats" denoise) | $3 | $4 | $(stage_ms "$out.stats" guides) | $(stage_ms "$out.stats" "path trace") |" >>"$rows"
        echo "$name $spp spp: noisy $1, ours $2, OIDN $3" >&2
    done
    # photon mapping (16 passes) and cone tracing (its default), without and with --denoise
    row="| $name"
    for method in "--method pm --spp 16" ""; do
        for dn in "" --denoise; do
            # shellcheck disable=SC2086
            ./build/vct render "scenes/suite/$file" $method --seed 1 --size "$SIZE" "$SIZE" $dn \
                --stats $ambient -o out/denoise/other.pfm >out/denoise/other.stats 2>&1
            row="$row | $(./build/vct compare out/denoise/other.pfm "$ref" | sed -n 's/^nrmse //p' |
                cut -c1-6)"
        done
    done
    echo "$row |" >>"$others"
done
stamp=$(bench/stamp.sh bench/denoise.sh "$@")
{
    echo "# Denoising the path tracer: the engine's filter and Intel Open Image Denoise"
    echo
    echo "$stamp"
    echo
    echo "Each suite scene at ${SIZE}x${SIZE}, path traced at 4 and 16 spp (seed 1), then denoised"
    echo "by the engine's filter (\`--denoise\`: the path tracer's direct and indirect light apart,"
    echo "each divided by the albedo and through à-trous passes (three and five) guided by normals,"
    echo "depth and its own per-pixel variance, edge pixels fitted on their neighbours' normals"
    echo "and depths, the direct part kept where the filter moved it further than its noise"
    echo "explains) and by OIDN's RT filter (HDR,"
    echo "the same albedo and normal guides, as clean auxiliaries). NRMSE against the suite's"
    echo "reference; times in ms: our filter's device time, OIDN's filter call on the same"
    echo "CPU (the second call), the guides' device time (both filters use them) and the path"
    echo "tracer's."
    echo
    for spp in 4 16; do
        awk -F'|' -v spp="$spp" '$3 + 0 == spp && $7 + 0 > 0 {
                n++; e[n] = $5 / $7; t[n] = $6 / $8 }
            END {
                if (!n) exit
                for (i = 1; i <= n; ++i) { se += e[i]; st += t[i]; if (e[i] > worst) worst = e[i] }
                printf "At %d spp, over %d scenes: our NRMSE is %.2fx OIDN'"'"'s on average (at worst %.2fx),\n", spp, n, se / n, worst
                printf "in %.2fx its time on average.\n\n", st / n
            }' "$rows"
    done
    echo "| scene | spp | noisy NRMSE | ours | ours ms | OIDN | OIDN ms | guides ms | path trace ms |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    cat "$rows"
    echo
    echo "## Photon mapping and cone tracing"
    echo
    echo "The same filter without the path tracer's variance, estimated from the image instead; for"
    echo "cone tracing on its indirect term alone. NRMSE against the same references: photon mapping"
    echo "at 16 passes, cone tracing at its default."
    echo
    echo "| scene | pm | pm, denoised | vct | vct, denoised |"
    echo "|---|---:|---:|---:|---:|"
    cat "$others"
} >doc/results/denoise.md
cat doc/results/denoise.md
