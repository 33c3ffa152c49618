#!/bin/sh
# Where cone tracing's error lies, term by term and surface by surface. On
# each suite scene: cone tracing at its default with its AOVs, its direct
# term against the path tracer's direct light (its `direct` AOV at
# --max-depth 1, 4096 spp: the first surface's light from the lights and
# emitters, and the background seen, which is what cone tracing's direct
# term holds; at 512 spp its own noise, 0.067 of the room lit by two small
# panels' mean, was most of what the column measured), the
# rest (its indirect light) against the reference less that, and the
# surfaces (by the normal's axis) that hold the largest share of the
# indirect term's error (bench/error_split.py). Writes
# doc/results/error_split.md, and each scene's error image (vct compare) to
# out/suite/NAME/error_vct.png.
# usage: bench/error_split.sh [SIZE]   (default 128; the suite's references)
set -eu
cd "$(dirname "$0")/.."
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
SIZE=${1:-128}
rows=$work/rows.md
: >"$rows"
suite_with_references error_split | while read -r name file ambient; do
    ref=out/suite/$name/reference.pfm
    # shellcheck disable=SC2086
    ./build/vct render "scenes/suite/$file" $ambient --size "$SIZE" "$SIZE" --aov \
        -o "$work/vct.pfm" >/dev/null 2>&1
    # shellcheck disable=SC2086
    ./build/vct render "scenes/suite/$file" $ambient --size "$SIZE" "$SIZE" --method pt \
        --spp 4096 --max-depth 1 --seed 1 --aov -o "$work/pt.pfm" >/dev/null 2>&1
    ./build/vct compare "$work/vct.pfm" "$ref" --error-image "out/suite/$name/error_vct.png" \
        >/dev/null
    tools/python.sh bench/error_split.py "$name" "$work/vct.pfm" "$work/pt_direct.pfm" "$ref" \
        >>"$rows"
    echo "error_split: $name" >&2
done
spp=$(cat out/suite/*/reference.spp 2>/dev/null | sort -n -u | paste -s -d / -)
stamp=$(bench/stamp.sh bench/error_split.sh "$@")
{
    echo "# Where cone tracing's error lies"
    echo
    echo "$stamp"
    echo
    echo "Each suite scene at ${SIZE}x${SIZE}, cone tracing at its default against the suite's"
    echo "path-traced reference (${spp:-?} spp, by scene). Its direct term (the \`direct\` AOV) against the"
    echo "path tracer's direct light (its \`direct\` AOV at \`--max-depth 1\`, 4096 spp: the light of the"
    echo "first surface from the lights and emitters, and the background seen), and the rest of its image,"
    echo "the indirect light, against the reference less that: each term's mean over its"
    echo "reference's, and its NRMSE over the reference image's mean. The last columns name"
    echo "the surfaces, by the axis their normal lies within 26 degrees of (\`other\`: none),"
    echo "that hold the largest share of the indirect term's squared error, their indirect"
    echo "light over the reference's, and that share. Where the camera sees glass or a mirror,"
    echo "cone tracing's direct term holds the light of what lies behind them, which the path"
    echo "tracer finds on longer paths: those scenes are not split. Error images:"
    echo "\`out/suite/NAME/error_vct.png\` (\`vct compare --error-image\`)."
    echo
    echo "| scene | NRMSE | direct: mean | its NRMSE | indirect: mean | its NRMSE | worst surfaces | their indirect: mean | their share |"
    echo "|---|---:|---:|---:|---:|---:|---|---:|---:|"
    cat "$rows"
} >doc/results/error_split.md
echo "wrote doc/results/error_split.md" >&2
