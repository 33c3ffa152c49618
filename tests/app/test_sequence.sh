#!/bin/sh
# Animation through the command line: frames A to B of a sequence, rendered
# by one process through one device scene (which keeps what a frame does not
# move), equal renders of each frame alone, bit for bit, by every method;
# a moving camera and light (the nodes that carry them) do the same; a
# sequence on two devices gives one device's files; a pattern without a
# frame number and a scene without an animation are refused, leaving no
# file.
# Usage: test_sequence.sh VCT SOURCE_DIR
set -u
VCT=$1
SRC=$2
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
SCENE="$SRC/scenes/instanced_spheres.gltf"
failures=0
ok() { echo "ok   $*"; }
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

for m in raycast whitted pt pm vct; do
    case $m in
    pt) extra="--spp 2" ;;
    pm) extra="--spp 2 --photons 4096" ;;
    whitted) extra="--subsample 4" ;;
    *) extra="" ;;
    esac
    # frames 11 to 13: the sphere moves between each (the roll lasts 48 frames)
    # shellcheck disable=SC2086
    if ! "$VCT" render "$SCENE" --method $m --size 48 36 $extra --frames 11:13 \
        -o "$DIR/${m}_%02d.pfm" >"$DIR/log" 2>&1; then
        cat "$DIR/log"
        fail "$m: the sequence did not render"
        continue
    fi
    for f in 11 12 13; do
        # shellcheck disable=SC2086
        "$VCT" render "$SCENE" --method $m --size 48 36 $extra --frame $f \
            -o "$DIR/alone_${m}_$f.pfm" >/dev/null 2>&1
        if cmp -s "$DIR/${m}_$f.pfm" "$DIR/alone_${m}_$f.pfm"; then
            ok "$m frame $f of the sequence equals frame $f alone"
        else
            fail "$m frame $f of the sequence differs from frame $f alone"
        fi
    done
    cmp -s "$DIR/${m}_11.pfm" "$DIR/${m}_13.pfm" &&
        fail "$m: frames 11 and 13 are the same image: nothing moved"
done

# The camera and the light ride their nodes (moving_camera.gltf): frames of
# the sequence equal frames alone; cone tracing relights its voxels.
MOVING="$SRC/scenes/moving_camera.gltf"
for m in raycast pt vct; do
    case $m in
    pt) extra="--spp 2" ;;
    vct) extra="--voxel-res 32" ;;
    *) extra="" ;;
    esac
    # shellcheck disable=SC2086
    "$VCT" render "$MOVING" --method $m --size 40 30 $extra --frames 6:8 \
        -o "$DIR/cam_${m}_%d.pfm" >"$DIR/log" 2>&1 || { cat "$DIR/log"; fail "$m: camera sequence"; }
    same=0
    for f in 6 7 8; do
        # shellcheck disable=SC2086
        "$VCT" render "$MOVING" --method $m --size 40 30 $extra --frame $f \
            -o "$DIR/cam_alone_${m}_$f.pfm" >/dev/null 2>&1
        cmp -s "$DIR/cam_${m}_$f.pfm" "$DIR/cam_alone_${m}_$f.pfm" && same=$((same + 1))
    done
    if [ $same -eq 3 ] && ! cmp -s "$DIR/cam_${m}_6.pfm" "$DIR/cam_${m}_8.pfm"; then
        ok "$m: a moving camera and light, frames 6 to 8 equal each frame alone"
    else
        fail "$m: a moving camera and light: $same of 3 frames equal frames alone"
    fi
done

# --stats: what each frame rebuilt. A moving camera and light: after the
# first frame no BVH and no voxels, the light alone; a moving instance:
# the two-level structure's top level alone.
"$VCT" render "$MOVING" --method vct --voxel-res 32 --size 32 24 --frames 0:2 --stats \
    -o "$DIR/st_%d.pfm" >/dev/null 2>"$DIR/stats"
rows=$(awk '$1 ~ /^[12]$/ && NF == 7 && $3 == 0 && $4 == 0 && $5 == 0 && $6 == 1' "$DIR/stats" | wc -l)
if [ "$rows" -eq 2 ] && grep -q '^frame .*seconds.*BVH.*BVH moved.*voxels.*light' "$DIR/stats"; then
    ok "--stats: a moving camera and light rebuild only the voxels' light"
else
    cat "$DIR/stats"
    fail "--stats: the per-frame table of a moving camera and light"
fi
"$VCT" render "$SCENE" --method raycast --size 32 24 --frames 11:12 --stats \
    -o "$DIR/si_%d.pfm" >/dev/null 2>"$DIR/stats"
if awk '$1 == 12 && NF == 7 && $3 == 0 && $4 == 1' "$DIR/stats" | grep -q .; then
    ok "--stats: a moving instance rebuilds the top level alone"
else
    cat "$DIR/stats"
    fail "--stats: the per-frame table of a moving instance"
fi

# A sequence on two devices (each holding a device scene): one device's files.
for m in whitted pt; do
    case $m in
    pt) extra="--spp 2" ;;
    *) extra="--subsample 4" ;;
    esac
    # shellcheck disable=SC2086
    POCL_DEVICES="pthread pthread" "$VCT" render "$SCENE" --device 0,1 --method $m --size 48 36 \
        $extra --frames 11:13 -o "$DIR/two_${m}_%02d.pfm" >"$DIR/log" 2>&1 ||
        { cat "$DIR/log"; fail "$m: a sequence on two devices did not render"; }
    same=0
    for f in 11 12 13; do
        cmp -s "$DIR/two_${m}_$f.pfm" "$DIR/${m}_$f.pfm" && same=$((same + 1))
    done
    if [ $same -eq 3 ]; then
        ok "$m: frames 11 to 13 on two devices equal one device's"
    else
        fail "$m: on two devices, $same of 3 frames equal one device's"
    fi
done

# --video: the frames encoded by ffmpeg where it is installed, refused with
# what to do where it is not (before anything renders).
if command -v ffmpeg >/dev/null 2>&1; then
    "$VCT" render "$MOVING" --method raycast --size 32 24 --frames 2:4 -o "$DIR/v/f_%02d.png" \
        --video "$DIR/v/fly.mp4" >/dev/null 2>"$DIR/log"
    frames=$(ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries stream=nb_read_frames -of csv=p=0 "$DIR/v/fly.mp4" 2>/dev/null)
    if [ "$frames" = 3 ] && [ ! -e "$DIR/v/fly.partial.mp4" ]; then
        ok "--video: 3 frames encoded by ffmpeg"
    else
        cat "$DIR/log"
        fail "--video: the video holds '$frames' frames"
    fi
else
    if PATH=/nonexistent "$VCT" render "$MOVING" --frames 2:4 -o "$DIR/v/f_%02d.png" \
        --video "$DIR/v/fly.mp4" >/dev/null 2>"$DIR/log"; then
        fail "--video without ffmpeg was accepted"
    elif grep -q "ffmpeg is not installed" "$DIR/log" && [ ! -e "$DIR/v" ]; then
        ok "--video without ffmpeg: refused before rendering"
    else
        cat "$DIR/log"
        fail "--video without ffmpeg: no message, or frames written"
    fi
fi

refused() { # name expected-text args...
    name=$1 text=$2
    shift 2
    if "$VCT" render "$@" >"$DIR/out" 2>"$DIR/err"; then
        fail "$name: accepted"
    elif grep -q -- "$text" "$DIR/err" && [ -z "$(ls "$DIR"/refused_* 2>/dev/null)" ]; then
        ok "$name: refused, no file"
    else
        fail "$name: $(cat "$DIR/err")"
    fi
}
refused "a pattern without a number" "needs one frame number" "$SCENE" --frames 0:1 \
    -o "$DIR/refused_x.png"
refused "a scene without an animation" "has no animation" "$SRC/scenes/cornell_box.gltf" \
    --frames 0:1 -o "$DIR/refused_%d.png"
refused "--frame without an animation" "has no animation" "$SRC/scenes/cornell_box.gltf" \
    --frame 3 -o "$DIR/refused_x.png"
refused "--frames B before A" "A <= B" "$SCENE" --frames 5:2 -o "$DIR/refused_%d.png"
refused "--video of PFM frames" "PNG or EXR" "$SCENE" --frames 0:1 -o "$DIR/refused_%d.pfm" \
    --video "$DIR/refused.mp4"
refused "--video without --frames" "give --frames" "$SCENE" -o "$DIR/refused_x.png" \
    --video "$DIR/refused.mp4"

[ "$failures" -eq 0 ] && echo "test_sequence: all passed"
exit "$failures"
