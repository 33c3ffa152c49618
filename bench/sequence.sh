#!/bin/sh
# A short sequence of the suite's animated scene for the manual: frames 0,
# 12 and 24 of lamp_room's "slide" (the table slides towards the wall and
# back), cone traced at 240x180 through one device scene, side by side in
# doc/lamp_room_slide.png; doc/results/sequence.md holds it, stamped.
# usage: bench/sequence.sh
set -eu
cd "$(dirname "$0")/.."
# shellcheck source=bench/suite_env.sh
. bench/suite_env.sh
./build/vct render scenes/suite/lamp_room.gltf --size 240 180 --frames 0:24 --stats \
    -o "$work/f_%02d.png" >/dev/null 2>"$work/stats.txt"
tools/python.sh - "$work" <<'PY'
import sys
from PIL import Image
work = sys.argv[1]
frames = [Image.open(f"{work}/f_{k:02d}.png").convert("RGB") for k in (0, 12, 24)]
strip = Image.new("RGB", (sum(f.width for f in frames) + 8 * (len(frames) - 1), frames[0].height),
                  (255, 255, 255))
x = 0
for f in frames:
    strip.paste(f, (x, 0))
    x += f.width + 8
strip.save("doc/lamp_room_slide.png")
PY
rebuilt=$(awk '$1 == "frame" && $2 == "seconds" { on = 1; next }
    on && $1 ~ /^[0-9]+$/ && NF == 7 && $1 > 0 { n++; s += $2; v += $5 }
    END { printf "%.2f s a frame after the first, voxels built again in %d of %d", s / n, v, n }' \
    "$work/stats.txt")
{
    echo "# A short sequence: lamp_room.s \"slide\""
    echo
    bench/stamp.sh bench/sequence.sh
    echo
    echo "\`vct render scenes/suite/lamp_room.gltf --size 240 180 --frames 0:24\`: frames 0, 12"
    echo "and 24 of the suite's animated scene, cone traced; the table slides towards the wall"
    echo "(its shadow and the light it bounces with it). $rebuilt (the table"
    echo "is geometry: the voxels follow it)."
    echo
    echo "![Frames 0, 12 and 24 of lamp_room's slide](../lamp_room_slide.png)"
} >doc/results/sequence.md
cat doc/results/sequence.md
