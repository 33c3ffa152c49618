#!/bin/sh
# vct compile fills an empty kernel cache with every program that rendering
# the scene needs: after it, a render by each method, with the passes a user
# may add, compiles nothing. Usage: test_compile.sh VCT SOURCE_DIR
set -u
VCT=$1
SRC=$2
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
export VCT_CACHE_DIR="$DIR/cache"
SCENE="$SRC/scenes/cornell_box.gltf"
failures=0
ok() { echo "ok   $*"; }
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

"$VCT" compile "$SCENE" 2>"$DIR/compile.log"
rc=$?
compiled=$(sed -n 's/^vct compile: \([0-9]*\) kernel programs compiled.*/\1/p' "$DIR/compile.log")
if [ "$rc" -eq 0 ] && [ "${compiled:-0}" -gt 0 ]; then ok "vct compile: $compiled programs"; else
    fail "vct compile: exit $rc, programs '${compiled:-}'"; cat "$DIR/compile.log"; fi

# each render's --stats line: "kernel programs: N compiled, M from the cache"
render() { # NAME ARGS...
    name=$1
    shift
    "$VCT" render "$SCENE" --size 64 48 --spp 2 -o "$DIR/$name.pfm" --stats "$@" \
        >"$DIR/$name.log" 2>&1
    line=$(grep "^kernel programs:" "$DIR/$name.log")
    case "$line" in
    "kernel programs: 0 compiled, "*) ok "$name after vct compile: $line" ;;
    *) fail "$name after vct compile: '$line'"; tail -5 "$DIR/$name.log" ;;
    esac
}
render vct --method vct --denoise
render pt --method pt --denoise
render pt_plain --method pt
render pm --method pm --denoise
render raycast --method raycast --subsample 8
render whitted --method whitted --subsample 8

# one device at a time: binaries are per device
"$VCT" compile "$SCENE" --device all >/dev/null 2>"$DIR/err"
[ $? -eq 1 ] && grep -q "one device at a time" "$DIR/err" && ok "a device list is refused" ||
    fail "a device list: not refused with a message"
[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
