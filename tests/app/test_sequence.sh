#!/bin/sh
# Animation through the command line: frames A to B of a sequence, rendered
# by one process through one device scene (which keeps what a frame does not
# move), equal renders of each frame alone, bit for bit, by every method;
# a pattern without a frame number, a scene without an animation and a
# sequence on several devices are refused, leaving no file.
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
refused "--frames on two devices" "one device" "$SCENE" --frames 0:1 --device 0,0 \
    -o "$DIR/refused_%d.png"
refused "--frames B before A" "A <= B" "$SCENE" --frames 5:2 -o "$DIR/refused_%d.png"

[ "$failures" -eq 0 ] && echo "test_sequence: all passed"
exit "$failures"
