#!/bin/sh
# The command line's conventions: --help and --version exit 0 and print to
# stdout; every command has its own --help; doc/cli.md is what
# `vct --reference` prints today; every option the reference lists under a
# command is taken by that command's parser, and an option it lists under
# another command only is refused, naming the option.
# Usage: test_cli.sh VCT VCT_VIEW SOURCE_DIR
set -u
VCT=$1
VIEW=$2
SRC=$3
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
failures=0
ok() { echo "ok   $*"; }
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# expect_exit CODE NAME ARGS...: the exit code and a non-empty stdout.
expect_exit() {
    code=$1 name=$2
    shift 2
    "$@" >"$DIR/out" 2>"$DIR/err"
    rc=$?
    if [ "$rc" -eq "$code" ] && [ -s "$DIR/out" ]; then ok "$name (exit $rc)"; else
        fail "$name: exit $rc, expected $code"; cat "$DIR/err"; fi
}
expect_exit 0 "vct --help" "$VCT" --help
expect_exit 0 "vct -h" "$VCT" -h
expect_exit 0 "vct --version" "$VCT" --version
for cmd in devices info render voxelize compile compare; do
    expect_exit 0 "vct $cmd --help" "$VCT" $cmd --help
done
expect_exit 0 "vct-view --help" "$VIEW" --help
grep -q "^vct [0-9]*\.[0-9]*\.[0-9]* (library [0-9.]*, kernel interface [0-9]*)" "$DIR/out" ||
    "$VCT" --version | grep -q "kernel interface" || fail "--version names no kernel interface"

# No command: the usage on stderr, exit 2. An unknown command: exit 2.
"$VCT" >/dev/null 2>&1; [ $? -eq 2 ] && ok "no command: exit 2" || fail "no command: not exit 2"
"$VCT" --bogus >/dev/null 2>"$DIR/err"
[ $? -eq 2 ] && grep -q -- "--bogus" "$DIR/err" && ok "unknown command named" ||
    fail "unknown command"

# The reference page is the parser's tables as they are.
"$VCT" --reference >"$DIR/cli.md"
if cmp -s "$DIR/cli.md" "$SRC/doc/cli.md"; then ok "doc/cli.md is what vct --reference prints"; else
    fail "doc/cli.md differs from vct --reference (regenerate: vct --reference > doc/cli.md)"
    diff "$SRC/doc/cli.md" "$DIR/cli.md" | head -20
fi

# Every option of every command in the reference, fed to that command: the
# parser knows it (any refusal is about its value or the missing scene).
awk '/^## `vct/ { cmd = $3; sub(/`$/, "", cmd); prog = $2; sub(/^`/, "", prog) }
     /^## `vct-view/ { cmd = "-"; prog = "vct-view" }
     /^\| `/ { match($0, /`--[a-z-]+/); print prog, cmd, substr($0, RSTART + 1, RLENGTH - 1) }' \
    "$SRC/doc/cli.md" >"$DIR/options"
count=0
while read -r prog cmd option; do
    count=$((count + 1))
    if [ "$prog" = "vct-view" ]; then set -- "$VIEW" "$option"; else set -- "$VCT" "$cmd" "$option"; fi
    "$@" >/dev/null 2>"$DIR/err"
    if grep -q "unknown option\|not an option" "$DIR/err"; then
        fail "$prog $cmd $option: refused as unknown"; cat "$DIR/err"
    fi
done <"$DIR/options"
[ "$count" -gt 60 ] && ok "$count command options in the reference, each taken by its command" ||
    fail "only $count options read from doc/cli.md"

# An option of another command is refused, naming it and its command.
"$VCT" info scene.obj --spp 5 >/dev/null 2>"$DIR/err"
rc=$?
[ $rc -eq 2 ] && grep -q -- "--spp is not an option of this command (it is one of vct render's)" \
    "$DIR/err" && ok "vct info --spp refused" || { fail "vct info --spp: exit $rc"; cat "$DIR/err"; }
"$VCT" info scene.obj -o out.png >/dev/null 2>"$DIR/err"
[ $? -eq 2 ] && grep -q -- "unknown option -o" "$DIR/err" && ok "vct info -o refused" ||
    { fail "vct info -o accepted"; cat "$DIR/err"; }
"$VCT" compare a.pfm b.pfm --size 4 4 >/dev/null 2>"$DIR/err"
[ $? -eq 2 ] && grep -q -- "--size" "$DIR/err" && ok "vct compare --size refused" ||
    fail "vct compare --size accepted"
# Values: counts and kinds, each message names the option.
"$VCT" render scene.obj --size 64 >/dev/null 2>"$DIR/err"
grep -q -- "--size needs 2 values" "$DIR/err" && ok "--size with one value" || fail "--size 64"
"$VCT" render scene.obj --camera-pos -1 2 x >/dev/null 2>"$DIR/err"
grep -q -- '--camera-pos: "x" is not a finite number' "$DIR/err" && ok "--camera-pos -1 2 x" ||
    { fail "--camera-pos -1 2 x"; cat "$DIR/err"; }
"$VCT" render scene.obj --tone curvy >/dev/null 2>"$DIR/err"
grep -q -- '--tone takes filmic or clip, not "curvy"' "$DIR/err" && ok "--tone curvy" ||
    { fail "--tone curvy"; cat "$DIR/err"; }
# Options after the scene and before it, negative numbers as values.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$DIR/tri.obj"
if "$VCT" render --method raycast "$DIR/tri.obj" --size 8 6 --dir-light 0 0 -1 1 1 1 \
    -o "$DIR/tri.pfm" >/dev/null 2>"$DIR/err" && [ "$(head -c 12 "$DIR/tri.pfm" | sed -n 2p)" = "8 6" ]; then
    ok "options on both sides of the scene, a negative value"
else
    fail "render --method raycast tri.obj --size 8 6 --dir-light 0 0 -1 1 1 1"; cat "$DIR/err"
fi

# --denoise with cone tracing filters its indirect term alone: without one,
# the image is the same bits as without --denoise.
CORNELL=$SRC/scenes/cornell_box.gltf
"$VCT" render "$CORNELL" --size 24 16 --effect indirect=off -o "$DIR/plain.pfm" >/dev/null 2>&1
"$VCT" render "$CORNELL" --size 24 16 --effect indirect=off --denoise -o "$DIR/dn.pfm" >/dev/null 2>&1
cmp -s "$DIR/plain.pfm" "$DIR/dn.pfm" && ok "cone tracing's --denoise leaves direct light alone" ||
    fail "cone tracing's --denoise changed an image without indirect light"
# Its indirect light is filtered by default (--indirect-filter 3): 0 turns
# the filter off, --denoise takes it through all 5 passes; three images.
for f in 0 3 5; do
    "$VCT" render "$CORNELL" --size 24 16 --voxel-res 32 --indirect-filter $f \
        -o "$DIR/if$f.pfm" >/dev/null 2>&1 || fail "--indirect-filter $f did not render"
done
"$VCT" render "$CORNELL" --size 24 16 --voxel-res 32 -o "$DIR/if_default.pfm" >/dev/null 2>&1
"$VCT" render "$CORNELL" --size 24 16 --voxel-res 32 --denoise -o "$DIR/if_dn.pfm" >/dev/null 2>&1
if cmp -s "$DIR/if3.pfm" "$DIR/if_default.pfm" && cmp -s "$DIR/if5.pfm" "$DIR/if_dn.pfm" &&
    ! cmp -s "$DIR/if0.pfm" "$DIR/if3.pfm" && ! cmp -s "$DIR/if3.pfm" "$DIR/if5.pfm"; then
    ok "--indirect-filter: 3 by default, 5 with --denoise, 0 unfiltered, each its own image"
else
    fail "--indirect-filter 0, 3 and 5 against the default and --denoise"
fi
"$VCT" render "$CORNELL" --indirect-filter 6 -o "$DIR/no.pfm" >/dev/null 2>"$DIR/err"
grep -q -- "--indirect-filter" "$DIR/err" && [ ! -e "$DIR/no.pfm" ] && ok "--indirect-filter 6 refused" ||
    { fail "--indirect-filter 6"; cat "$DIR/err"; }

# The path tracer's --aov: its direct and indirect light beside the image,
# which they add up to, and the image the same bits as without the AOVs
# (whose sums hold the colour alone).
"$VCT" render "$CORNELL" --method pt --size 24 16 --spp 8 --max-depth 3 -o "$DIR/pt.pfm" \
    >/dev/null 2>&1
"$VCT" render "$CORNELL" --method pt --size 24 16 --spp 8 --max-depth 3 --aov \
    -o "$DIR/pt_aov.pfm" >/dev/null 2>&1
if cmp -s "$DIR/pt.pfm" "$DIR/pt_aov.pfm" &&
    "$SRC/tools/python.sh" - "$DIR/pt_aov.pfm" "$DIR/pt_aov_direct.pfm" \
        "$DIR/pt_aov_indirect.pfm" <<'PY'; then
import sys
import numpy as np
def pfm(path):
    with open(path, "rb") as f:
        f.readline()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        return np.fromfile(f, "<f4" if scale < 0 else ">f4").reshape(h, w, 3)
image, direct, indirect = (pfm(p) for p in sys.argv[1:4])
sys.exit(not (np.abs(direct + indirect - image).max() <= 1e-6 * image.max()
              and direct.mean() > 0 and indirect.mean() > 0))
PY
    ok "pt --aov: direct + indirect is the image, the same bits as without --aov"
else
    fail "pt --aov: no direct and indirect light adding up to the image"
fi

echo "$failures failed"
[ "$failures" -eq 0 ]
