#!/bin/sh
# A project outside vct builds against the installed package, through its
# CMake package (shared and static) and through pkg-config, runs, and
# renders the Cornell box by every method through the installed kernels:
# the images equal the in-tree `vct render` ones bit for bit.
# Usage: test_consumer.sh SOURCE_DIR BUILD_DIR VCT_PROGRAM
set -eu
SRC=$1
BUILD=$2
VCT=$3
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
PREFIX="$DIR/prefix"
SCENE="$SRC/scenes/cornell_box.gltf"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

cmake --install "$BUILD" --prefix "$PREFIX" >/dev/null
for f in include/vct/vct.h share/vct/kernels/vct_types.h share/vct/kernels/README.md; do
    [ -f "$PREFIX/$f" ] || fail "not installed: $f"
done
ls "$PREFIX"/lib*/libvct.so "$PREFIX"/lib*/libvct.a >/dev/null || fail "libraries not installed"

cmake -S "$SRC/tests/consumer" -B "$DIR/cmake" -DCMAKE_PREFIX_PATH="$PREFIX" >"$DIR/cmake.log" 2>&1 ||
    { cat "$DIR/cmake.log"; fail "find_package(vct) failed"; exit 1; }
cmake --build "$DIR/cmake" >"$DIR/build.log" 2>&1 || { cat "$DIR/build.log"; fail "consumer build"; exit 1; }
PCDIR=$(dirname "$(ls "$PREFIX"/lib*/pkgconfig/vct.pc)")
# shellcheck disable=SC2046
cc -std=c11 "$SRC/tests/consumer/main.c" -o "$DIR/pkgconfig_consumer" \
    $(PKG_CONFIG_PATH="$PCDIR" pkg-config --cflags --libs vct) -Wl,-rpath,"$(dirname "$PCDIR")" ||
    fail "pkg-config build"

# the consumer's settings: 4 spp, 2 photon passes of 16384 photons, 64^3 voxels
"$VCT" render "$SCENE" --method raycast --size 128 128 -o "$DIR/ref_raycast.pfm" >/dev/null 2>&1
"$VCT" render "$SCENE" --method whitted --size 128 128 -o "$DIR/ref_whitted.pfm" >/dev/null 2>&1
"$VCT" render "$SCENE" --method pt --spp 4 --size 128 128 -o "$DIR/ref_pt.pfm" >/dev/null 2>&1
"$VCT" render "$SCENE" --method pm --spp 2 --photons 16384 --size 128 128 \
    -o "$DIR/ref_pm.pfm" >/dev/null 2>&1
"$VCT" render "$SCENE" --size 128 128 --voxel-res 64 -o "$DIR/ref_vct.pfm" >/dev/null 2>&1

run() { # name program kernel-dir-expected [env]
    name=$1
    shift
    if ! "$@" "$SCENE" "$DIR/$name" >"$DIR/$name.log" 2>&1; then
        cat "$DIR/$name.log"
        fail "$name did not run"
        return
    fi
    grep -q "kernels from $PREFIX/share/vct/kernels" "$DIR/$name.log" ||
        { cat "$DIR/$name.log"; fail "$name did not read the installed kernels"; }
    grep -q "^device 0:" "$DIR/$name.log" || fail "$name listed no device"
    for m in raycast whitted pt pm vct; do
        if cmp -s "$DIR/${name}_$m.pfm" "$DIR/ref_$m.pfm"; then
            echo "ok   $name: $m image equals vct render's"
        else
            fail "$name: $m image differs from vct render's"
        fi
    done
}
run cmake_shared "$DIR/cmake/vct_consumer"
# A static library cannot find its install prefix: the documented variable says.
run cmake_static env VCT_KERNEL_DIR="$PREFIX/share/vct/kernels" "$DIR/cmake/vct_consumer_static"
[ -x "$DIR/pkgconfig_consumer" ] && run pkgconfig "$DIR/pkgconfig_consumer"
[ "$failures" -eq 0 ] && echo "test_consumer: all passed"
exit "$failures"
