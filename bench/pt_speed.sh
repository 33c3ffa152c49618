#!/bin/sh
# The path tracer's speed against Mitsuba 3's (its LLVM backend, on the same
# number of threads as PoCL's compute units): the same scenes, size, samples,
# depth and Russian roulette, each timed in one run of this script. vct's time
# is the path-trace stage's device time, the fastest of 3 runs (kernels
# compiled and cached first); Mitsuba's the fastest of 3 renders after one
# that compiles its kernels.
# Dr.Jit needs LLVM 16 or newer: Debian 12's libllvm19 is installed here when
# missing. Writes doc/results/pt_speed.md.
# usage: bench/pt_speed.sh
set -eu
cd "$(dirname "$0")/.."
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
llvm=/usr/lib/x86_64-linux-gnu/libLLVM-19.so
[ -e "$llvm" ] || apt-get install -y -q libllvm19 >/dev/null ||
    { echo "pt_speed: libllvm19 cannot be installed; Mitsuba's LLVM backend needs it" >&2; exit 1; }
export DRJIT_LIBLLVM_PATH="$llvm" THREADS="$POCL_CPU_MAX_CU_COUNT"
W=256 H=256 DEPTH=8 RR=3
rows="$work/rows.md"
: >"$rows"
for entry in "cornell_box ../cornell_box.gltf 256" "lamp_room lamp_room.gltf 64" \
    "dense_hall dense_hall.gltf 64" "atrium atrium.gltf 64"; do
    set -- $entry
    name=$1 file=scenes/suite/$2 spp=$3
    ambient=$(awk -v n="$name" '$1 == n' scenes/suite/suite.txt | grep -o -- '--ambient [0-9. ]*' || true)
    ./build/vct render "$file" --method pt --spp 1 --size 16 16 -o "$work/warm.pfm" >/dev/null 2>&1
    for k in 1 2 3; do
        ./build/vct render "$file" --method pt --spp "$spp" --size $W $H --max-depth $DEPTH \
            $ambient -o "$work/vct.pfm" --stats >"$work/vct.log" 2>&1
        awk '/^path trace / { printf "%.3f\n", $3 / 1000; exit }' "$work/vct.log"
    done >"$work/vct_s"
    vct_s=$(sort -n "$work/vct_s" | head -1)
    mts_s=$(tools/python.sh bench/pt_mitsuba.py "$file" "$spp" $W $H $DEPTH $RR \
        ${ambient:+--ambient ${ambient#--ambient }})
    ratio=$(awk "BEGIN { printf \"%.2f\", $vct_s / $mts_s }")
    tris=$(sed -n 's/.*: \([0-9]*\) triangles.*/\1/p' "$work/vct.log" | head -1)
    echo "| $name | $tris | $spp | $vct_s | $mts_s | **$ratio** |" >>"$rows"
    echo "pt_speed: $name: vct $vct_s s, Mitsuba $mts_s s ($ratio)" >&2
done
stamp=$(bench/stamp.sh bench/pt_speed.sh)
mkdir -p doc/results
{
    echo "# The path tracer against Mitsuba 3"
    echo
    echo "$stamp"
    echo
    echo "${W}x$H, at most $DEPTH surfaces a path, Russian roulette after $RR surfaces, next-event"
    echo "estimation to every light. vct: the path-trace stage's device time on PoCL with"
    echo "$POCL_CPU_MAX_CU_COUNT compute units. Mitsuba 3 (\`llvm_ad_rgb\`: its \`path\` integrator"
    echo "vectorized by Dr.Jit's LLVM backend, rays traced by Embree) on $POCL_CPU_MAX_CU_COUNT"
    echo "threads. Each is the fastest of 3 renders. At every surface vct samples each punctual"
    echo "light and one emitter triangle, Mitsuba one light picked at random: where a scene has"
    echo "both (lamp_room: a point light in an emitting shade), vct traces two shadow rays a"
    echo "surface to Mitsuba's one, for less noise a sample."
    echo
    echo "| scene | triangles | spp | vct s | Mitsuba s | vct / Mitsuba |"
    echo "|---|---:|---:|---:|---:|---:|"
    cat "$rows"
} >doc/results/pt_speed.md
cat doc/results/pt_speed.md
