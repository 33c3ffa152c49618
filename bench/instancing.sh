#!/bin/sh
# One BVH over every triangle against two levels (a BVH per mesh under one
# over the instances): device memory and build time, and what the second
# level costs the rays (a ray-cast frame and a 16-spp path-traced frame at
# 320x240, device time of the render stages from --stats), on the file whose
# sphere 64 nodes place and on the suite's heaviest scene (four meshes, none
# shared: two levels forced). Writes doc/results/instancing.md.
# usage: bench/instancing.sh
set -eu
cd "$(dirname "$0")/.."
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/make_instanced.py
tools/python.sh scenes/suite/make_suite.py >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rows=$work/rows.md
# device ms of the stages that trace rays, summed from --stats' table
render_ms() {
    awk '($1 == "ray" && $2 == "cast") || ($1 == "path" && $2 == "trace") { s += $(NF - 3) } END { printf "%.1f", s }'
}
for scene in scenes/instanced_spheres.gltf scenes/suite/dense_hall.gltf; do
    for levels in one two; do
        # a warm-up run compiles the kernel variants, so that builds are timed alone
        ./build/vct render "$scene" --method raycast --size 64 48 --bvh-levels $levels \
            -o "$work/warm.pfm" >/dev/null 2>&1
        ./build/vct render "$scene" --method pt --spp 1 --size 64 48 --bvh-levels $levels \
            -o "$work/warm.pfm" >/dev/null 2>&1
        line=$(./build/vct render "$scene" --method raycast --size 320 240 --bvh-levels $levels \
            --stats -o "$work/rc_$levels.pfm" 2>&1 >"$work/rc_stats.txt" | grep '^accel:')
        mib=$(echo "$line" | sed -n 's/.* \([0-9.]*\) MiB.*/\1/p')
        build=$(echo "$line" | sed -n 's/.*built in \([0-9.]*\) ms.*/\1/p')
        rc=$(render_ms <"$work/rc_stats.txt")
        ./build/vct render "$scene" --method pt --spp 16 --size 320 240 --bvh-levels $levels \
            --stats -o "$work/pt_$levels.pfm" 2>/dev/null >"$work/pt_stats.txt"
        pt=$(render_ms <"$work/pt_stats.txt")
        printf '| %s | %s | %s | %s | %s | %s |\n' "$(basename "$scene" .gltf)" "$levels" "$mib" \
            "$build" "$rc" "$pt" >>"$rows"
    done
    same=different
    cmp -s "$work/rc_one.pfm" "$work/rc_two.pfm" && cmp -s "$work/pt_one.pfm" "$work/pt_two.pfm" &&
        same=identical
    echo "$(basename "$scene" .gltf): one- and two-level images $same" >>"$work/same.txt"
done
{
    echo "# Instancing: one BVH or two levels"
    echo
    bench/stamp.sh bench/instancing.sh
    echo
    echo "\`--bvh-levels one\` builds one BVH over every triangle of the flattened scene;"
    echo "\`two\` builds a BVH per mesh, once however many instances place it, under a BVH over"
    echo "the instances (the default where a mesh is shared). Memory is the device memory the"
    echo "structure holds (the scene's world-space triangles included), build the host wall time"
    echo "of the build; the frame columns are the device time of the ray-cast frame and of a"
    echo "16-spp path-traced frame at 320x240."
    echo
    echo "| scene | levels | memory MiB | build ms | ray cast ms | path trace ms |"
    echo "|---|---|---:|---:|---:|---:|"
    cat "$rows"
    echo
    sed 's/^/- /' "$work/same.txt"
} >doc/results/instancing.md
cat doc/results/instancing.md
