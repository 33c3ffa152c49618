#!/bin/sh
# What a frame of a moving scene costs, by what moved, and whether what did
# not move stays still. Sequences rendered through one device scene with
# --stats: the seconds of each frame after the first and what it rebuilt,
# for a camera and a light that move (moving_camera.gltf) and a sphere that
# rolls (instanced_spheres.gltf); the device time of cone tracing's voxel
# stages summed over the rolling frames; the update of one moved object by
# stage against a full build, rebuilt and carried (--light-carry), on the
# spheres, the lamp room and the dense hall (bench/make_moving.py moves its
# pedestal); frames a second at 512x512. Then flicker: the RMS change,
# between two frames of the roll, of the pixels the sphere and its shadow
# do not touch, by cone tracing and by a 256-spp path tracer (its samples
# repeat from frame to frame, so its change there is the light that the
# sphere really moves). Writes doc/results/dynamic.md.
# usage: bench/dynamic.sh
set -eu
cd "$(dirname "$0")/.."
export VCT_DEVICE="${VCT_DEVICE:-Portable Computing Language}"
export POCL_MAX_PTHREAD_COUNT=${POCL_MAX_PTHREAD_COUNT:-2} POCL_CPU_MAX_CU_COUNT=${POCL_CPU_MAX_CU_COUNT:-2}
tools/python.sh scenes/make_instanced.py
tools/python.sh scenes/make_moving_camera.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size="--size 256 192"
rows=$work/rows.md
# mean seconds and rebuilds over frames after the first, from --stats' per-frame table
frame_rows() { # label
    awk -v label="$1" '
        $1 == "frame" && $2 == "seconds" { on = 1; next }
        on && $1 ~ /^[0-9]+$/ && NF == 7 { n++; if (n > 1) { s += $2; b += $3; t += $4; v += $5; l += $6; k++ } }
        END { printf "| %s | %.3f | %.1f | %.1f | %.1f | %.1f |\n", label, s / k, b / k, t / k, v / k, l / k }'
}
for method in raycast pt vct; do
    case $method in
    pt) extra="--spp 16" ;;
    *) extra="" ;;
    esac
    # a warm-up compiles the kernels
    # shellcheck disable=SC2086
    ./build/vct render scenes/moving_camera.gltf --method $method $extra --size 32 24 --frames 0:1 \
        -o "$work/warm_%d.pfm" >/dev/null 2>&1
    # shellcheck disable=SC2086
    ./build/vct render scenes/moving_camera.gltf --method $method $extra $size --frames 0:8 --stats \
        -o "$work/cam_%d.pfm" >/dev/null 2>"$work/cam.txt"
    frame_rows "$method, camera and light move" <"$work/cam.txt" >>"$rows"
    # shellcheck disable=SC2086
    ./build/vct render scenes/instanced_spheres.gltf --method $method $extra $size --frames 8:16 \
        --stats -o "$work/roll_%d.pfm" >"$work/roll_stages_$method.txt" 2>"$work/roll_$method.txt"
    frame_rows "$method, a sphere rolls" <"$work/roll_$method.txt" >>"$rows"
done
# cone tracing's device time by stage over the rolling frames (--stats' stage table)
stages=$(awk '
    $1 == "voxelize" { geo += $2 }
    $1 == "octree" && $2 == "build" { geo += $3 }
    ($1 == "brick" || $1 == "radiance") && $2 ~ /^(creation|filtering)$/ { bricks += $3 }
    $1 == "light" && $2 == "injection" { direct += $3 }
    $1 == "light" && $2 == "bounce" && $3 ~ /^[0-9.]+$/ { bounce += $3 }
    $1 == "light" && $2 == "bounce" && $3 == "rest" { bounce += $4 }
    $1 == "vct" { frame += $3 }
    END { printf "| %.0f | %.0f | %.0f | %.0f | %.0f |", geo, bricks, direct, bounce, frame }' \
    "$work/roll_stages_vct.txt")
# the light carried over frames against every bounce again: the moving
# light of moving_camera.gltf (it stops at frame 48), frames 40 to 60
for mode in full carry; do
    flag=""
    [ $mode = carry ] && flag="--light-carry"
    # shellcheck disable=SC2086
    ./build/vct render scenes/moving_camera.gltf --method vct $size --frames 40:60 $flag --stats \
        -o "$work/${mode}_%02d.pfm" >/dev/null 2>"$work/$mode.txt"
done
carry_rows=$(tools/python.sh - "$work" <<'PY'
import sys
sys.path.insert(0, "bench")
import numpy as np
from pfm import read_pfm
work = sys.argv[1]
def table(mode):
    rows = {}
    on = False
    for line in open(f"{work}/{mode}.txt"):
        f = line.split()
        if f[:2] == ["frame", "seconds"]:
            on = True
        elif on and len(f) == 7 and f[0].isdigit():
            rows[int(f[0])] = (float(f[1]), int(f[5]))
    return rows
full, carry = table("full"), table("carry")
def nrmse(k):
    a, b = read_pfm(f"{work}/carry_{k:02d}.pfm"), read_pfm(f"{work}/full_{k:02d}.pfm")
    return np.sqrt(np.mean((a - b) ** 2)) / np.mean(b)
moving = range(41, 49)
print("| every bounce again | %.3f | %.3f | - | - |" % (
    np.mean([full[k][0] for k in moving]), np.mean([full[k][0] for k in range(49, 61)])))
settled = [k for k in range(49, 61) if carry[k][1] == 0]
print("| carried (`--light-carry`) | %.3f | %.3f | %.4f | %s |" % (
    np.mean([carry[k][0] for k in moving]), np.mean([carry[k][0] for k in range(49, 61)]),
    np.mean([nrmse(k) for k in moving]),
    ", ".join("%.4f" % nrmse(k) for k in range(48, (settled[0] if settled else 60) + 1))))
PY
)
# One object moves: each stage's device time for frame F alone (a full
# build and a frame) and for frames F to F + 8 (the same, then 8 updates
# and frames); an update is the difference over 8. Rebuilt (the default)
# and carried (--light-carry: moved triangles voxelized alone, direct light
# kept where nothing moved reaches, the carried bounce spread over renders).
stage_table() { # file: "stage ms" lines from --stats' stage table
    awk '$1 == "stage" && $2 == "device" { on = 1; next }
         on && NF >= 5 && $(NF - 3) ~ /^[0-9.]+$/ {
             name = $1; for (i = 2; i <= NF - 4; ++i) name = name " " $i
             print name "\t" $(NF - 3); next }
         on { on = 0 }' "$1"
}
update_ms() { # scene frame flag: "stage<TAB>full<TAB>update" lines
    # shellcheck disable=SC2086
    ./build/vct render "$1" --method vct $size --frame "$2" --stats $3 \
        -o "$work/one.pfm" >"$work/one.txt" 2>/dev/null
    # shellcheck disable=SC2086
    ./build/vct render "$1" --method vct $size --frames "$2:$(($2 + 8))" --stats $3 \
        -o "$work/two_%d.pfm" >"$work/two.txt" 2>/dev/null
    stage_table "$work/one.txt" >"$work/one.tsv"
    stage_table "$work/two.txt" >"$work/two.tsv"
    awk -F '\t' 'NR == FNR { one[$1] = $2; next } { print $1 "\t" one[$1] "\t" ($2 - one[$1]) / 8 }' \
        "$work/one.tsv" "$work/two.tsv"
}
update_rows() { # scene frame: "| stage | full | rebuilt | ratio | carried | ratio |" rows
    update_ms "$1" "$2" "" >"$work/rebuilt.tsv"
    update_ms "$1" "$2" --light-carry >"$work/carried.tsv"
    awk -F '\t' 'NR == FNR { carried[$1] = $3; next }
        { full = $2; a = $3; b = carried[$1]
          frame = $1 ~ /^vct / ? " (the frame)" : ""
          if (frame == "") { F += full; A += a; B += b }
          ra = full ? sprintf("%.2f", a / full) : "-"
          rb = full ? sprintf("%.2f", b / full) : "-"
          printf "| %s%s | %.1f | %.1f | %s | %.1f | %s |\n", $1, frame, full, a, ra, b, rb }
        END { printf "| **all but the frame** | **%.1f** | **%.1f** | **%.2f** | **%.1f** | **%.2f** |\n",
              F, A, A / F, B, B / F }' "$work/carried.tsv" "$work/rebuilt.tsv"
}
tools/python.sh scenes/suite/make_suite.py >/dev/null
# the suite's dense hall: its pedestal (12 of 105,624 triangles) slides under the model
tools/python.sh bench/make_moving.py scenes/suite/dense_hall.gltf "$work/hall_move.gltf" 2 0.5 0 0.3 1
spheres_update=$(update_rows scenes/instanced_spheres.gltf 12)
lamp_update=$(update_rows scenes/suite/lamp_room.gltf 12)
hall_update=$(update_rows "$work/hall_move.gltf" 6)
# cone tracing at 512x512 while the sphere rolls: frames a second, rebuilt and carried
fps_of() { # flag
    # shellcheck disable=SC2086
    ./build/vct render scenes/instanced_spheres.gltf --method vct --size 512 512 --frames 11:15 \
        --stats $1 -o "$work/big_%d.pfm" >/dev/null 2>"$work/big.txt"
    awk '$1 == "frame" && $2 == "seconds" { on = 1; next }
        on && $1 ~ /^[0-9]+$/ && NF == 7 { n++; if (n > 1) { s += $2; k++ } }
        END { printf "%.2f s a frame, %.2f frames a second", s / k, k / s }' "$work/big.txt"
}
fps=$(fps_of "")
fps_carried=$(fps_of --light-carry)
# flicker between frames 12 and 13 of the roll; carried light as in a
# sequence that has rolled for a while (frames 4 to 13)
for f in 12 13; do
    ./build/vct render scenes/instanced_spheres.gltf --method raycast $size --frame $f \
        -o "$work/rc_$f.pfm" >/dev/null 2>&1
    ./build/vct render scenes/instanced_spheres.gltf --method vct $size --frame $f \
        -o "$work/vct_$f.pfm" >/dev/null 2>&1
    ./build/vct render scenes/instanced_spheres.gltf --method pt --spp 256 $size --frame $f \
        -o "$work/pt_$f.pfm" >/dev/null 2>&1
done
# shellcheck disable=SC2086
./build/vct render scenes/instanced_spheres.gltf --method vct $size --frames 4:13 --light-carry \
    -o "$work/carried_%d.pfm" >/dev/null 2>&1
flicker() { tools/python.sh bench/temporal_flicker.py "$work/$1_12.pfm" "$work/$1_13.pfm" \
    "$work/rc_12.pfm" "$work/rc_13.pfm" 4; }
vct_flicker=$(flicker vct)
carried_flicker=$(flicker carried)
pt_flicker=$(flicker pt)
{
    echo "# Scenes that move: what a frame costs, and what stays still"
    echo
    bench/stamp.sh bench/dynamic.sh
    echo
    echo "Sequences at 256x192 through one device scene (\`vct render --frames ... --stats\`),"
    echo "averaged over the frames after the first: the frame's wall time and what it rebuilt"
    echo "(BVHs built, BVHs moved: a top level placed again or boxes refit, voxels, the voxels' light)."
    echo "A camera and a light that"
    echo "move rebuild no BVH and no voxels; cone tracing relights its voxels. A rolling sphere"
    echo "rebuilds the top level over its 64 instances, and cone tracing its voxels whole. The"
    echo "two scenes differ (a few boxes; 64 spheres of 5,120 triangles): compare within one."
    echo
    echo "| sequence | seconds a frame | BVH | BVH moved | voxels | light |"
    echo "|---|---:|---:|---:|---:|---:|"
    cat "$rows"
    echo
    echo "Where cone tracing's rolling frames spend their device time (ms, all 9 frames): the"
    echo "voxels' geometry (voxelization and octree), their bricks (creation and filtering, of"
    echo "the light too), direct light, bounces, and the camera's frame. Rebuilt, the bounces dominate."
    echo
    echo "| voxelize + octree | bricks | direct light | bounces | frame |"
    echo "|---:|---:|---:|---:|---:|"
    echo "$stages"
    echo
    echo "One object moves: cone tracing's device time (ms) by stage for a full build and its"
    echo "frame (frame F alone), and for an update with its frame (frames F to F + 8, less frame F"
    echo "alone, over 8), rebuilt (the default: the voxels and their light built again, bit for"
    echo "bit a fresh build) and carried (\`--light-carry\`: the moved triangles voxelized alone and"
    echo "merged, direct light kept wherever nothing that moved reaches it, and the bounce gathered"
    echo "from the light before by a quarter of the voxels each frame and by those lit anew). Ratio:"
    echo "the update over the full build. Single frames vary by 10-30 % from run to run."
    echo
    echo "One sphere of the 64 rolls (1.6 % of 327,684 triangles):"
    echo
    echo "| stage | full build | update, rebuilt | ratio | update, carried | ratio |"
    echo "|---|---:|---:|---:|---:|---:|"
    echo "$spheres_update"
    echo
    echo "The suite's \`lamp_room\`, its table sliding (50 of its 150 triangles):"
    echo
    echo "| stage | full build | update, rebuilt | ratio | update, carried | ratio |"
    echo "|---|---:|---:|---:|---:|---:|"
    echo "$lamp_update"
    echo
    echo "The suite's \`dense_hall\`, its pedestal sliding under the model (12 of 105,624 triangles;"
    echo "\`bench/make_moving.py\`):"
    echo
    echo "| stage | full build | update, rebuilt | ratio | update, carried | ratio |"
    echo "|---|---:|---:|---:|---:|---:|"
    echo "$hall_update"
    echo
    echo "Cone tracing at 512x512 while the sphere rolls (frames 12 to 15): rebuilt $fps;"
    echo "carried $fps_carried."
    echo
    echo "Light carried over frames (\`--light-carry\`) against every bounce gathered again, on"
    echo "the light of \`moving_camera.gltf\`, which moves until frame 48 and then stays: seconds"
    echo "a frame while it moves (frames 41 to 48) and after (49 to 60), the NRMSE of the carried"
    echo "frames against the recomputed ones while it moves (mean), and from the frame it stops"
    echo "until the carried light has settled (no more bounces gathered)."
    echo
    echo "| voxels' light | s a frame, moving | s a frame, after | NRMSE moving | NRMSE after the stop, frame by frame |"
    echo "|---|---:|---:|---:|---|"
    echo "$carry_rows"
    echo
    echo "Flicker where nothing moved: between frames 12 and 13 of the roll, the RMS change of"
    echo "the pixels that the sphere and its shadow do not touch (the ray caster's changed pixels"
    echo "grown by 4), over the image mean. The path tracer repeats its samples from frame to"
    echo "frame, so its change there is indirect light the sphere really moves."
    echo
    echo "| method | change where nothing moved | pixels |"
    echo "|---|---:|---:|"
    echo "| cone tracing | $(echo "$vct_flicker" | cut -d' ' -f1) | $(echo "$vct_flicker" | cut -d' ' -f2) |"
    echo "| cone tracing, light carried | $(echo "$carried_flicker" | cut -d' ' -f1) | $(echo "$carried_flicker" | cut -d' ' -f2) |"
    echo "| path tracing, 256 spp | $(echo "$pt_flicker" | cut -d' ' -f1) | $(echo "$pt_flicker" | cut -d' ' -f2) |"
} >doc/results/dynamic.md
cat doc/results/dynamic.md
