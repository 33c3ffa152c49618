#!/bin/sh
# vct-view on a virtual X display (Xvfb with Mesa, started here): each case
# opens the window, renders a frame of the Cornell box, reads the
# framebuffer back and compares it with `vct render` of the same camera and
# settings, pixel for pixel within one 8-bit step. Keys drive the method
# and effect switches, and a resize, on the way. Where no display can be
# opened the test is skipped (exit 77) with the reason, never passed.
# usage: test_view.sh VCT_VIEW VCT PNG_COMPARE
set -u
VIEW=$1 VCT=$2 COMPARE=$3
SCENE=${VCT_SOURCE_DIR:-.}/scenes/cornell_box.gltf
TMP=$(mktemp -d)
XPID=""
cleanup() {
    [ -n "$XPID" ] && kill "$XPID" 2>/dev/null
    rm -rf "$TMP"
}
trap cleanup EXIT INT TERM

skip() {
    echo "SKIPPED: $*"
    exit 77
}

if command -v Xvfb >/dev/null 2>&1; then
    n=90
    while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do
        n=$((n + 1))
        [ $n -gt 140 ] && skip "no free X display number between :90 and :140"
    done
    Xvfb ":$n" -screen 0 640x480x24 -nolisten tcp >"$TMP/xvfb.log" 2>&1 &
    XPID=$!
    tries=0
    while [ ! -e "/tmp/.X11-unix/X$n" ]; do
        tries=$((tries + 1))
        if [ $tries -gt 100 ] || ! kill -0 "$XPID" 2>/dev/null; then
            skip "Xvfb :$n did not start: $(tail -n 3 "$TMP/xvfb.log")"
        fi
        sleep 0.1
    done
    export DISPLAY=":$n"
elif [ -z "${DISPLAY:-}" ]; then
    skip "no Xvfb (Debian package xvfb) and no DISPLAY"
fi

failed=0
# case NAME "VIEW ARGS" "RENDER ARGS"
case_compare() {
    name=$1 view_args=$2 render_args=$3
    # shellcheck disable=SC2086
    "$VIEW" "$SCENE" --voxel-res 32 --display host --capture "$TMP/$name.view.png" $view_args \
        >"$TMP/$name.view.log" 2>&1
    rc=$?
    if [ $rc -eq 3 ]; then
        cat "$TMP/$name.view.log"
        skip "vct-view could not open a window: $(tail -n 1 "$TMP/$name.view.log")"
    fi
    # shellcheck disable=SC2086
    "$VCT" render "$SCENE" --voxel-res 32 -o "$TMP/$name.offline.png" $render_args \
        >"$TMP/$name.render.log" 2>&1
    render_rc=$?
    if [ $rc -ne 0 ] || [ $render_rc -ne 0 ]; then
        echo "FAIL $name: vct-view exited $rc, vct render $render_rc"
        cat "$TMP/$name.view.log" "$TMP/$name.render.log"
        failed=1
        return
    fi
    if "$COMPARE" "$TMP/$name.view.png" "$TMP/$name.offline.png" 1; then
        echo "ok   $name"
    else
        echo "FAIL $name: the window differs from the offline render"
        failed=1
    fi
}

case_compare vct "--size 96 64" "--size 96 64"
case_compare vct64 "--size 64 64" "--size 64 64"
cp "$TMP/vct64.offline.png" "$TMP/vct-ref.png"
case_compare raycast "--size 80 80 --method raycast" "--size 80 80 --method raycast"
case_compare whitted "--size 80 80 --method whitted" "--size 80 80 --method whitted"
case_compare whitted-subsampled "--size 80 80 --method whitted --subsample 8" "--size 80 80 --method whitted --subsample 8"
case_compare pathtracer "--size 64 64 --keys 3" "--size 64 64 --method pt --spp 1"
case_compare photon-mapping "--size 48 48 --method pm --photons 8192" "--size 48 48 --method pm --photons 8192 --spp 1"
case_compare pathtracer-denoised "--size 64 64 --keys 3,n" "--size 64 64 --method pt --spp 1 --denoise"
case_compare vct-denoised "--size 64 64 --denoise" "--size 64 64 --denoise"
case_compare indirect-off "--size 64 64 --keys F1" "--size 64 64 --effect indirect=off"
case_compare shadows-off "--size 64 64 --keys 1,F4" "--size 64 64 --method raycast --effect shadows=off"
case_compare resized "--size 64 64 --keys size=72x40" "--size 72 40"
case_compare exposure "--size 48 48 --exposure 0 --keys +,+" "--size 48 48 --exposure 1"
# the default tone: automatic exposure and the filmic curve, in both
case_compare auto-tone "--size 48 48 --method raycast" "--size 48 48 --method raycast"
case_compare clip-tone "--size 48 48 --tone clip" "--size 48 48 --tone clip"
case_compare soft-shadows "--size 48 48 --light-radius 60" "--size 48 48 --light-radius 60"
case_compare soft-off "--size 48 48 --light-radius 60 --keys F5" "--size 48 48 --light-radius 60 --effect soft_shadows=off"

# Two PoCL devices render each frame (row bands; the path tracer a sample
# each per frame): the window shows what one device renders offline.
export POCL_DEVICES="pthread pthread"
case_compare devices-vct "--size 64 48 --device 0,1" "--size 64 48 --device 0"
case_compare devices-whitted "--size 64 48 --method whitted --subsample 4 --device 0,1" \
    "--size 64 48 --method whitted --subsample 4 --device 0"
case_compare devices-pt "--size 48 48 --keys 3 --device 0,1" "--size 48 48 --method pt --spp 2 --device 0"
grep -q "device 0 working.*device 1 working" "$TMP/devices-vct.view.log" ||
    { echo "FAIL devices: both devices did not work on the frame"; cat "$TMP/devices-vct.view.log"; failed=1; }
unset POCL_DEVICES

# Animation: period (.) steps a frame on, comma (,) a frame back (the scene posed, a camera
# the animation carries followed); the window shows what vct render
# --frame N renders. Space plays: the title says so and frames go on.
anim_compare() { # name scene keys frame args
    name=$1 scene=$2 keys=$3 frame=$4 args=$5
    # shellcheck disable=SC2086
    "$VIEW" "$scene" --display host --capture "$TMP/$name.view.png" --keys "$keys" $args \
        >"$TMP/$name.view.log" 2>&1
    # shellcheck disable=SC2086
    "$VCT" render "$scene" --frame "$frame" -o "$TMP/$name.offline.png" $args \
        >"$TMP/$name.render.log" 2>&1
    if "$COMPARE" "$TMP/$name.view.png" "$TMP/$name.offline.png" 1 &&
        grep -q "frame $frame (" "$TMP/$name.view.log"; then
        echo "ok   $name"
    else
        echo "FAIL $name: the window at frame $frame differs from vct render --frame $frame"
        cat "$TMP/$name.view.log"
        failed=1
    fi
}
ANIMATED=${VCT_SOURCE_DIR:-.}/scenes/instanced_spheres.gltf
MOVING=${VCT_SOURCE_DIR:-.}/scenes/moving_camera.gltf
p=period
anim_compare roll-step "$ANIMATED" "$p,$p,$p,$p,$p,$p,$p,$p,$p,$p,$p,$p,$p,comma" 12 \
    "--size 64 48 --method raycast"
anim_compare camera-step "$MOVING" "$p,$p,$p,$p,$p,$p,$p,$p,$p,$p" 10 "--size 64 48 --method raycast"
anim_compare camera-step-vct "$MOVING" "$p,$p,$p,$p,$p" 5 "--size 48 36 --voxel-res 32"
POCL_DEVICES="pthread pthread" anim_compare roll-step-devices "$ANIMATED" "$p,$p,$p,$p,$p,$p" 6 \
    "--size 64 48 --method raycast --device 0,1"
"$VIEW" "$ANIMATED" --display host --size 32 24 --method raycast --keys "space" \
    --capture "$TMP/play.png" >"$TMP/play.log" 2>&1
grep -q "frame 1 (0.04 s) playing" "$TMP/play.log" ||
    { echo "FAIL play: the title does not say it plays frame 1"; cat "$TMP/play.log"; failed=1; }

# The voxel view at a coarse level: a window of octree cells, not black.
"$VIEW" "$SCENE" --voxel-res 32 --display host --size 64 64 --keys "4,[,[" \
    --capture "$TMP/voxels.png" >"$TMP/voxels.log" 2>&1 ||
    { echo "FAIL voxels: $(cat "$TMP/voxels.log")"; failed=1; }
grep -q "level 3/5" "$TMP/voxels.log" || { echo "FAIL voxels: level not 3/5"; cat "$TMP/voxels.log"; failed=1; }

# A moved light re-injects and re-filters, and nothing is voxelized again.
"$VIEW" "$SCENE" --voxel-res 32 --display host --size 48 48 --keys "frame,right" \
    --capture "$TMP/light.png" >"$TMP/light.log" 2>&1 ||
    { echo "FAIL light: $(cat "$TMP/light.log")"; failed=1; }
second=$(grep "^vct-view |" "$TMP/light.log" | sed -n 2p)
case "$second" in
*"light injection"*"light bounce"*) ;;
*) echo "FAIL light: the second frame did not re-inject: $second"; failed=1 ;;
esac
case "$second" in
*voxelize* | *"octree build"*) echo "FAIL light: the second frame re-voxelized: $second"; failed=1 ;;
esac
[ $failed -eq 0 ] && echo "ok   light move: $second"

# Interop where the device shares with GL (then it must match too), else a
# clear refusal naming the missing extension.
if "$VIEW" "$SCENE" --voxel-res 32 --display interop --size 64 64 \
    --capture "$TMP/interop.png" >"$TMP/interop.log" 2>&1; then
    "$COMPARE" "$TMP/interop.png" "$TMP/vct-ref.png" 1 || failed=1
elif grep -q "cl_khr_gl_sharing" "$TMP/interop.log"; then
    echo "ok   interop refused: $(grep cl_khr "$TMP/interop.log")"
else
    echo "FAIL interop: $(cat "$TMP/interop.log")"
    failed=1
fi

# Bad input: a clear message and a non-zero exit, no window left behind.
if "$VIEW" "$SCENE" --keys nosuchkey --capture "$TMP/bad.png" >"$TMP/bad.log" 2>&1; then
    echo "FAIL: an unknown key name was accepted"
    failed=1
fi
grep -q 'unknown key "nosuchkey"' "$TMP/bad.log" || { echo "FAIL: no message for a bad key"; failed=1; }
[ ! -e "$TMP/bad.png" ] || { echo "FAIL: a capture was written after an error"; failed=1; }
if "$VIEW" "$SCENE" --display sideways >"$TMP/bad.log" 2>&1; then
    echo "FAIL: --display sideways was accepted"
    failed=1
fi
if "$VIEW" "$SCENE" --method nope >"$TMP/bad.log" 2>&1 || ! grep -q "unknown --method nope" "$TMP/bad.log"; then
    echo "FAIL: --method nope: $(cat "$TMP/bad.log")"
    failed=1
fi
exit $failed
