#!/bin/sh
# Where cone tracing's light goes astray, bounce by bounce. On each suite
# scene: the image's mean after each of cone tracing's bounces
# (--bounces K --exact-bounces, K = 1 to 4, then its default with the rest
# of the series) beside the path tracer's at the same path length
# (--max-depth K + 1, 512 spp), both over the suite's reference mean, and
# what each bounce adds. A bounce that adds more than the one before it, or
# far more or less than the path tracer's, points at the bounces; a first
# column off points at the direct light. Writes doc/results/bounces.md.
# usage: bench/bounces.sh [SIZE]   (default 128; the suite's references)
set -eu
cd "$(dirname "$0")/.."
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
SIZE=${1:-128}
rows=$work/rows.md
: >"$rows"
mean_ratio() { # image, reference -> the image's mean over the reference's
    ./build/vct compare "$1" "$2" | sed -n 's/^mean_ratio //p'
}
suite_with_references bounces | while read -r name file ambient; do
    ref=out/suite/$name/reference.pfm
    vct="" pt=""
    for k in 1 2 3 4; do
        # shellcheck disable=SC2086
        ./build/vct render "scenes/suite/$file" $ambient --size "$SIZE" "$SIZE" --bounces $k \
            --exact-bounces -o "$work/vct.pfm" >/dev/null 2>&1
        vct="$vct $(mean_ratio "$work/vct.pfm" "$ref")"
        # shellcheck disable=SC2086
        ./build/vct render "scenes/suite/$file" $ambient --size "$SIZE" "$SIZE" --method pt \
            --spp 512 --max-depth $((k + 1)) -o "$work/pt.pfm" >/dev/null 2>&1
        pt="$pt $(mean_ratio "$work/pt.pfm" "$ref")"
    done
    # shellcheck disable=SC2086
    ./build/vct render "scenes/suite/$file" $ambient --size "$SIZE" "$SIZE" -o "$work/vct.pfm" \
        >/dev/null 2>&1
    whole=$(mean_ratio "$work/vct.pfm" "$ref")
    echo "$name $vct $whole $pt" | awk '{
        printf "| %s | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %.3f |", $1,
            $2, $7, $3, $8, $4, $9, $5, $10, $6
        printf " %+.3f / %+.3f | %+.3f / %+.3f | %+.3f / %+.3f |\n",
            $3 - $2, $8 - $7, $4 - $3, $9 - $8, $5 - $4, $10 - $9 }' >>"$rows"
    echo "bounces: $name" >&2
done
stamp=$(bench/stamp.sh bench/bounces.sh "$@")
{
    echo "# Cone tracing's light, bounce by bounce, against the path tracer's"
    echo
    echo "$stamp"
    echo
    echo "Each suite scene at ${SIZE}x${SIZE}. Each cell: cone tracing's image mean after K"
    echo "bounces (\`--bounces K --exact-bounces\`) / the path tracer's with paths of K + 1"
    echo "segments (\`--max-depth\`, 512 spp), both over the suite reference's mean; then cone"
    echo "tracing's default (4 bounces and the rest of the series); then what bounces 2, 3 and 4"
    echo "add to the one before, each beside the path tracer's. A bounce that adds more than"
    echo "the one before it, or far more or less than the path tracer's, points at the bounces;"
    echo "K = 1 off points at the direct light or the first gather. Under a sky (atrium,"
    echo "window_room, blinds_fins, long_hall) the path tracer's last surface also meets the sky"
    echo "its BSDF sample finds, which cone tracing's voxels hold one bounce later: there each"
    echo "of cone tracing's K lies between the path tracer's K and K + 1."
    echo
    echo "| scene | K = 1 | K = 2 | K = 3 | K = 4 | default | adds at 2 | adds at 3 | adds at 4 |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    cat "$rows"
} >doc/results/bounces.md
echo "wrote doc/results/bounces.md" >&2
