#!/bin/sh
# vct render under mpirun on this machine: 1, 2 and 4 ranks sharing its
# cores, one PoCL thread each. Wall time, speed-up and efficiency for an
# animation of 24 frames (path traced, 16 spp, 160x120) and for one
# path-traced frame (Cornell box, 256 spp, 256x256), and the bytes each rank
# hands to MPI per frame (from --stats), from which a cluster's traffic can
# be sized. Writes doc/results/cluster.md.
# usage: bench/cluster.sh
set -eu
cd "$(dirname "$0")/.."
if ! command -v mpirun >/dev/null; then
    echo "bench/cluster.sh: mpirun not found: tools/deps.sh installs Open MPI" >&2
    exit 1
fi
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=1 POCL_CPU_MAX_CU_COUNT=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
tools/python.sh scenes/make_instanced.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
seq_args="scenes/instanced_spheres.gltf --method pt --spp 16 --size 160 120 --frames 0:23"
frame_args="scenes/cornell_box.gltf --method pt --spp 256 --size 256 256"
# a warm-up run of each compiles the kernels, so that the runs below time rendering
# shellcheck disable=SC2086
./build/vct render $frame_args --spp 1 -o "$work/warm.pfm" >/dev/null 2>&1
# shellcheck disable=SC2086
./build/vct render $seq_args --frames 0:0 -o "$work/warm_%d.pfm" >/dev/null 2>&1
rows=$work/rows.md
traffic=$work/traffic.md
for what in sequence frame; do
    base=""
    for n in 1 2 4; do
        rm -rf "$work/out"
        t0=$(now)
        if [ $what = sequence ]; then
            # shellcheck disable=SC2086
            mpirun -np $n ./build/vct render $seq_args --stats -o "$work/out/f_%02d.pfm" \
                >"$work/log" 2>&1
        else
            # shellcheck disable=SC2086
            mpirun -np $n ./build/vct render $frame_args --stats -o "$work/out/frame.pfm" \
                >"$work/log" 2>&1
        fi
        t=$(echo "$(now) $t0" | awk '{ printf "%.2f", $1 - $2 }')
        [ -z "$base" ] && base=$t
        echo "$what $n $t $base" | awk '{ printf "| %s | %d | %.2f | %.2f | %.2f |\n", $1, $2, $3, $4 / $3, $4 / $3 / $2 }' >>"$rows"
        if [ $n -gt 1 ]; then
            # the rank table of --stats: rank host device work seconds sent
            awk -v what=$what -v n=$n '
                $1 == "rank" && $NF == "bytes" { on = 1; next }
                on && $1 ~ /^[0-9]+$/ {
                    rendered = what == "sequence" ? $(NF - 2) : 1
                    per_frame = rendered ? $NF / rendered : 0
                    printf "| %s | %d | %d | %.0f | %.0f |\n", what, n, $1, $(NF - 2), per_frame }
                on && $1 !~ /^[0-9]+$/ { on = 0 }' "$work/log" >>"$traffic"
        fi
    done
done
{
    echo "# Several processes: vct render under mpirun"
    echo
    bench/stamp.sh bench/cluster.sh
    echo
    echo "Ranks share this machine's cores, one PoCL thread each, so more ranks than cores"
    echo "cannot go faster: on a cluster each rank has a machine (or a device) of its own."
    echo "Wall time of the whole \`mpirun\` (scene loading, structure builds and file writes"
    echo "included). The sequence: \`instanced_spheres.gltf\`, frames 0 to 23, path traced at"
    echo "16 spp, 160x120, dealt a frame at a time. The frame: the Cornell box, 256 spp at"
    echo "256x256, its samples split between the ranks and summed exactly."
    echo
    echo "| work | ranks | seconds | speed-up | efficiency |"
    echo "|---|---:|---:|---:|---:|"
    cat "$rows"
    echo
    echo "What each rank hands to MPI (\`--stats\`' sent bytes), per frame it rendered. A"
    echo "sequence's worker sends each frame it renders to rank 0 (16 bytes a pixel), and rank 0"
    echo "answers each with the next frame's number; a path-traced frame's ranks send their exact"
    echo "sums (80 bytes a pixel) into a reduction. Its share is frames, or samples per pixel."
    echo
    echo "| work | ranks | rank | its share | bytes per frame |"
    echo "|---|---:|---:|---:|---:|"
    cat "$traffic"
} >doc/results/cluster.md
cat doc/results/cluster.md
