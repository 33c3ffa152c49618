#!/bin/sh
# Bad input to the vct commands: each case must exit non-zero, print a message
# naming the problem, and leave no output file behind.
# Usage: cli_errors.sh PATH/TO/vct
set -u
VCT="$1"
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
cd "$DIR" || exit 1
failures=0

# expect_failure NAME EXPECTED-TEXT ARGS...
expect_failure() {
    name="$1"
    text="$2"
    shift 2
    rm -f out.png out.pfm
    "$VCT" "$@" >stdout.txt 2>stderr.txt
    rc=$?
    if [ "$rc" -eq 0 ]; then
        echo "FAIL $name: exit code 0"; failures=$((failures + 1)); return
    fi
    if ! grep -q -- "$text" stderr.txt; then
        echo "FAIL $name: stderr lacks \"$text\":"; cat stderr.txt; failures=$((failures + 1)); return
    fi
    if ls out.* >/dev/null 2>&1; then
        echo "FAIL $name: an output file was left behind"; failures=$((failures + 1)); return
    fi
    echo "ok   $name (exit $rc): $(head -n 1 stderr.txt)"
}

printf 'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > nan.obj
printf 'v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n' > inf.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > index.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' > empty.obj
printf 'mtllib t.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > texture.obj
printf 'newmtl m\nKd 1 1 1\nmap_Kd missing.png\n' > t.mtl
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > ok.obj
printf 'this is not a scene\n' > garbage.gltf

expect_failure "missing file" "absent.obj" render absent.obj -o out.png
expect_failure "NaN vertex" "nan.obj: mesh \"defaultobject\" vertex 0 is not finite" render nan.obj -o out.png
expect_failure "infinite vertex" "vertex 1 is not finite" render inf.obj -o out.png
expect_failure "index out of range" "index.obj: line 4: a face uses vertex 9, but 3 are defined" render index.obj -o out.png
expect_failure "empty scene" "empty.obj: no triangles" render empty.obj -o out.png
expect_failure "missing texture" "names texture \"missing.png\", which does not exist" render texture.obj -o out.png
expect_failure "unreadable glTF" "garbage.gltf" render garbage.gltf -o out.png
# bad animation data: refused on load, naming the file, the animation and the channel
python3 "${VCT_SOURCE_DIR:-.}/tests/load/make_bad_animations.py" .
expect_failure "a key that is not a number" 'nan_key.gltf: animation "bad", the channel of node "tri": translation key 1' \
    render nan_key.gltf --frame 3 -o out.png
expect_failure "key times out of order" "key times must increase" render unordered.gltf -o out.png
expect_failure "a scale of 0" "scale key 1 (at 1 s): a scale of 0" render zero_scale.gltf -o out.png
python3 "${VCT_SOURCE_DIR:-.}/tests/load/make_cubic_animation.py" .
expect_failure "a cubic tangent that is not a number" \
    'cubic_nan_tangent.gltf: animation "splines", the translation channel of node "nodes\[0\]": key 0: a tangent is not finite' \
    render cubic_nan_tangent.gltf -o out.png
expect_failure "a cubic spline without its tangents" "sampler 0: 2 values for 2 keys: a cubic spline has 3 a key" \
    render cubic_short.gltf -o out.png
expect_failure "a channel naming no node" 'out of bounds (1) for "nodes"' render no_node.gltf \
    -o out.png
expect_failure "bad output name" "must end in .exr, .pfm or .png" render ok.obj -o out.jpg
expect_failure "bad size" "--size" render ok.obj --size 0 10 -o out.png
expect_failure "bad number" "not a finite number" render ok.obj --point-light 1 2 x 1 1 1 -o out.png
expect_failure "bad cone levels" "--cone-levels takes blend or nearest" render ok.obj --cone-levels bilinear -o out.png
expect_failure "unknown option" "unknown option --bogus" render ok.obj --bogus -o out.png
expect_failure "no such device" "device 99 does not exist" render ok.obj --device 99 -o out.png
expect_failure "degenerate camera" "do not define a view" render ok.obj --camera-pos 0 0 5 --look-at 0 0 5 -o out.png
# 2^30 cells' ranges take 8 GiB, which a large device can hold: a per-buffer
# limit of 1 GiB makes any device too small for them.
VCT_MAX_ALLOC_MIB=1024 expect_failure "grid beyond the device's memory" "lower" \
    render ok.obj --accel grid --grid-res 1024 -o out.png
expect_failure "unknown acceleration structure" "--accel takes bvh or grid" render ok.obj --accel kdtree -o out.png
expect_failure "unknown bvh builder" "--bvh-build takes clustered or linear" render ok.obj --bvh-build sah -o out.png
# A kernel that does not compile: the build log names the file and line.
cp -r "$(dirname "$VCT")/kernels" broken-kernels
printf 'this is not OpenCL C;\n' >> broken-kernels/render/raycast.cl
VCT_KERNEL_DIR="$DIR/broken-kernels" VCT_CACHE_DIR="$DIR/cache" \
    expect_failure "kernel build failure" "raycast.cl:[0-9]" render ok.obj --method raycast -o out.png
expect_failure "unwritable output" "could not write\|cannot create" render ok.obj -o /proc/out.png

# A scene with degenerate triangles renders, and says how many it has.
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nv 1 0 1\nf 1 2 3\nf 1 2 5\nf 1 5 4\n' > degenerate.obj
if "$VCT" render degenerate.obj --point-light 0.5 2 0.5 1 1 1 --size 32 32 -o out.pfm 2>stderr.txt >/dev/null &&
    grep -q "1 degenerate" stderr.txt && [ -s out.pfm ]; then
    echo "ok   degenerate triangles counted and rendered"
else
    echo "FAIL degenerate triangles:"; cat stderr.txt; failures=$((failures + 1))
fi

# A copy of the binary with no kernel directory beside it uses its embedded
# kernels and renders the same image bit for bit.
mkdir -p lone && cp "$VCT" lone/vct
if "$VCT" render ok.obj --point-light 0.2 0.2 1 1 1 1 --size 40 30 -o a.pfm >/dev/null 2>&1 &&
    VCT_KERNEL_DIR='' ./lone/vct render ok.obj --point-light 0.2 0.2 1 1 1 1 --size 40 30 -o b.pfm \
        >/dev/null 2>&1 && cmp -s a.pfm b.pfm; then
    echo "ok   a copied binary renders with its embedded kernels, identically"
else
    echo "FAIL copied binary"; failures=$((failures + 1))
fi

# The path tracer and compare commands, end to end.
e2e_ok=1
"$VCT" render ok.obj --method pt --spp 4 --point-light 0.2 0.2 1 1 1 1 --size 24 16 -o pt.pfm \
    >/dev/null 2>stderr.txt && grep -q "4 spp" stderr.txt || e2e_ok=0
"$VCT" compare pt.pfm pt.pfm >compare.txt && grep -q "^rmse 0$" compare.txt || e2e_ok=0
"$VCT" compare pt.pfm pt.pfm --error-image err.png >/dev/null && [ -s err.png ] || e2e_ok=0
# b.pfm (40x30) against pt.pfm (24x16): refused.
if "$VCT" compare pt.pfm b.pfm >/dev/null 2>&1; then e2e_ok=0; fi
if [ "$e2e_ok" -eq 1 ]; then
    echo "ok   path tracing, compare, error image, size mismatch refused"
else
    echo "FAIL path tracing or compare:"; cat stderr.txt compare.txt 2>/dev/null; failures=$((failures + 1))
fi
# Voxelization: bad resolutions, and structures beyond a (lowered) allocation limit.
expect_failure "voxel resolution not a power of two" "power of two" voxelize ok.obj --voxel-res 100 -o out.png
expect_failure "voxel bounds of size zero" "size must be positive" voxelize ok.obj --voxel-bounds 0 0 0 0 -o out.png
VCT_MAX_ALLOC_MIB=1 expect_failure "fragments beyond the allocation limit" "voxel-res 256 would fit" \
    voxelize ok.obj --voxel-res 1024 -o out.png
VCT_MAX_ALLOC_MIB=30 expect_failure "octree beyond the allocation limit" "neighbour links.*voxel-res 512 would fit" \
    voxelize ok.obj --voxel-res 1024 -o out.png
VCT_MAX_ALLOC_MIB=20 expect_failure "brick windows beyond the allocation limit" "brick windows.*voxel-res 256 would fit" \
    voxelize ok.obj --voxel-res 512 -o out.png
expect_failure "unknown brick pool kind" "auto, buffer or image" voxelize ok.obj --bricks texture -o out.png
# the brick pool: image3d where the device filters in hardware (GPUs), else buffer
if "$VCT" voxelize ok.obj --voxel-res 32 --size 24 24 --anisotropic -o vox.png >stdout.txt 2>stderr.txt &&
    grep -q "^fragments [0-9]*, voxels [0-9]*" stdout.txt && grep -q "level  5" stdout.txt &&
    grep -q "^bricks: [0-9]* .*anisotropic" stdout.txt && grep -q "^brick pool: \(buffer\|image3d\)" stdout.txt &&
    [ -s vox.png ]; then
    echo "ok   voxelize reports voxels, octree levels and bricks and renders them"
else
    echo "FAIL voxelize:"; cat stdout.txt stderr.txt; failures=$((failures + 1))
fi
expect_failure "pt without samples" "not an integer" render ok.obj --method pt --spp 0 -o out.png
expect_failure "unknown method" "unknown --method" render ok.obj --method magic -o out.png
expect_failure "unknown effect" "NAME=on or NAME=off" render ok.obj --effect sparkle=on -o out.png
expect_failure "effect without a value" "NAME=on or NAME=off" render ok.obj --effect ao -o out.png
expect_failure "too many diffuse cones" "not an integer in 1..16" render ok.obj --ambient 1 1 1 --cones 17 -o out.png
expect_failure "negative ambient" "ambient radiance" render ok.obj --ambient 1 -1 1 -o out.png
expect_failure "negative light radius" "radius -1" render ok.obj --point-light 0 2 0 1 1 1 --light-radius -1 -o out.png
expect_failure "sun radius of a radian or more" "below 1 radian" render ok.obj --dir-light 0 -1 0 1 1 1 --light-radius 1.5 -o out.png
expect_failure "bad cone step" "cone step" render ok.obj --ambient 1 1 1 --cone-step 0 -o out.png
expect_failure "too many bounces" "not an integer in 1..4" render ok.obj --bounces 9 -o out.png
expect_failure "photon mapping without light" "no lights, nothing emits" render ok.obj --method pm --size 8 8 -o out.png
expect_failure "photon radius larger than the scene" "larger than the scene" render ok.obj --method pm --point-light 0 0 1 1 1 1 --pm-radius 50 --size 8 8 -o out.png
expect_failure "zero photon radius" "positive distance" render ok.obj --method pm --point-light 0 0 1 1 1 1 --pm-radius 0 -o out.png
expect_failure "photon radius below precision" "can tell" render ok.obj --method pm --point-light 0 0 1 1 1 1 --pm-radius 1e-9 --size 8 8 -o out.png
expect_failure "photon kernel" "box or epanechnikov" render ok.obj --method pm --pm-kernel cone -o out.png
expect_failure "photons beyond the device" "photons per pass (--photons)" render ok.obj --method pm --point-light 0 0 1 1 1 1 --photons 1073741824 --size 8 8 -o out.pfm
# The plan: printed with reasons; a forced effect says so; the image is written.
if "$VCT" render ok.obj --plan --ambient 0.5 0.5 0.5 --effect specular=on --voxel-res 16 --size 16 16 \
    -o sky.png >stdout.txt 2>stderr.txt &&
    grep -q "^  indirect     on   diffuse material" stdout.txt &&
    grep -q "^  specular     on   forced on (the scene alone: off" stdout.txt &&
    grep -q "^  ao           on   ambient light" stdout.txt &&
    grep -q "^  soft_shadows off  no lights" stdout.txt &&
    grep -q "^  direct       off  no lights" stdout.txt && [ -s sky.png ]; then
    echo "ok   render --plan prints each effect, on or off, and why"
else
    echo "FAIL render --plan:"; cat stdout.txt stderr.txt; failures=$((failures + 1))
fi
# Which acceleration structure: info and render say, with its figures.
if "$VCT" info ok.obj >stdout.txt 2>stderr.txt &&
    grep -q "^accel: bvh 4-wide, clustered .* SAH cost .* MiB, built in" stdout.txt &&
    "$VCT" info ok.obj --accel grid >stdout.txt 2>stderr.txt &&
    grep -q "^accel: grid [0-9]*x[0-9]*x[0-9]* cells, [0-9]* references" stdout.txt &&
    "$VCT" render ok.obj --method raycast --bvh-build linear --size 8 8 -o lin.pfm \
        >stdout.txt 2>stderr.txt &&
    grep -q "^accel: bvh 4-wide, linear" stderr.txt && [ -s lin.pfm ]; then
    echo "ok   info and render name the acceleration structure"
else
    echo "FAIL accel lines:"; cat stdout.txt stderr.txt; failures=$((failures + 1))
fi

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "all bad-input cases rejected cleanly"
