#!/bin/sh
# vct render under mpirun, 2 and 3 ranks sharing this machine (one PoCL
# thread each): every method's image equals one process's, bit for bit (the
# path tracer summed exactly, the others in bands); a sequence dealt frame
# by frame gives one process's files; a rank killed in the middle of a
# sequence ends the job naming it and leaves only whole files, and
# --resume renders the rest, giving the uninterrupted run's files; ranks of
# two devices each give one device's image; what cannot be split is
# refused.
# Usage: test_mpi.sh VCT MPIEXEC SOURCE_DIR
set -u
VCT=$1
MPIEXEC=$2
SRC=$3
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
BOX="$SRC/scenes/cornell_box.gltf"
ANIMATED="$SRC/scenes/instanced_spheres.gltf"
# CI runs as root; ranks share the cores; no network between them
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
export POCL_MAX_PTHREAD_COUNT=1 POCL_CPU_MAX_CU_COUNT=1
failures=0
# a job that hangs fails the test instead of the CI run
mpi() { timeout 300 "$MPIEXEC" "$@"; }
ok() { echo "ok   $*"; }
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# One frame, every method: one process against 2 and 3 ranks.
for m in pt pm vct whitted raycast; do
    case $m in
    pt) extra="--spp 5" ;;
    pm) extra="--spp 4" ;; # enough photons that the bands' radii differ
    vct) extra="--voxel-res 32" ;;
    whitted) extra="--subsample 8" ;;
    raycast) extra="--subsample 4" ;;
    esac
    # shellcheck disable=SC2086
    "$VCT" render "$BOX" --method $m --size 48 37 $extra -o "$DIR/one_$m.pfm" >"$DIR/log" 2>&1 ||
        { cat "$DIR/log"; fail "$m: one process did not render"; continue; }
    for n in 2 3; do
        # shellcheck disable=SC2086
        if ! mpi -np $n "$VCT" render "$BOX" --method $m --size 48 37 $extra \
            -o "$DIR/mpi${n}_$m.pfm" >"$DIR/log" 2>&1; then
            cat "$DIR/log"
            fail "$m: $n ranks did not render"
        elif cmp -s "$DIR/one_$m.pfm" "$DIR/mpi${n}_$m.pfm"; then
            ok "$m: $n ranks give one process's image, bit for bit"
        else
            fail "$m: $n ranks differ from one process"
        fi
    done
done

# Ranks of two devices each (a device group per rank): one device's image.
for m in pt pm vct whitted; do
    case $m in
    pt) extra="--spp 5" ;;
    pm) extra="--spp 4" ;;
    vct) extra="--voxel-res 32" ;;
    whitted) extra="--subsample 8" ;;
    esac
    # shellcheck disable=SC2086
    if ! POCL_DEVICES="pthread pthread" mpi -np 2 "$VCT" render "$BOX" --device 0,1 \
        --method $m --size 48 37 $extra -o "$DIR/group_$m.pfm" >"$DIR/log" 2>&1; then
        cat "$DIR/log"
        fail "$m: 2 ranks of 2 devices did not render"
    elif cmp -s "$DIR/one_$m.pfm" "$DIR/group_$m.pfm"; then
        ok "$m: 2 ranks of 2 devices each give one device's image, bit for bit"
    else
        fail "$m: 2 ranks of 2 devices differ from one device"
    fi
done

# --stats names every rank with its share, time and bytes sent.
mpi -np 3 "$VCT" render "$BOX" --method pt --spp 3 --size 32 24 --stats \
    -o "$DIR/stats.pfm" >"$DIR/log" 2>&1
rows=$(grep -cE '^[0-2] +[^ ]+ .* +[0-9]+ +[0-9.]+ +[0-9]+$' "$DIR/log")
if grep -q '^rank .*samples.*sent bytes' "$DIR/log" && [ "$rows" -eq 3 ]; then
    ok "--stats lists the 3 ranks"
else
    cat "$DIR/log"
    fail "--stats: $rows rank rows"
fi

# A sequence of 6 frames dealt to 3 ranks: one process's files.
seq_args="--method pt --spp 2 --size 40 30 --frames 10:15"
# shellcheck disable=SC2086
"$VCT" render "$ANIMATED" $seq_args -o "$DIR/seq1/f_%02d.pfm" >"$DIR/log" 2>&1 ||
    { cat "$DIR/log"; fail "sequence: one process did not render"; }
# shellcheck disable=SC2086
mpi -np 3 "$VCT" render "$ANIMATED" $seq_args -o "$DIR/seq3/f_%02d.pfm" >"$DIR/log" 2>&1 ||
    { cat "$DIR/log"; fail "sequence: 3 ranks did not render"; }
same=0
for f in 10 11 12 13 14 15; do
    cmp -s "$DIR/seq1/f_$f.pfm" "$DIR/seq3/f_$f.pfm" && same=$((same + 1))
done
if [ $same -eq 6 ]; then
    ok "a sequence of 6 frames on 3 ranks gives one process's files"
else
    fail "a sequence on 3 ranks: $same of 6 files equal one process's"
fi

# A rank killed in the middle of a sequence, then --resume.
kill_args="--method pt --spp 160 --size 40 30 --frames 0:15"
# shellcheck disable=SC2086
"$VCT" render "$ANIMATED" $kill_args -o "$DIR/whole/f_%02d.pfm" >/dev/null 2>&1
mark="vct_test_mpi_$$"
# shellcheck disable=SC2086
env VCT_TEST_MARK=$mark timeout 300 "$MPIEXEC" -np 3 "$VCT" render "$ANIMATED" $kill_args \
    -o "$DIR/cut/f_%02d.pfm" >"$DIR/cut.log" 2>&1 &
job=$!
victim=""
tries=0
while [ $tries -lt 600 ] && [ -z "$victim" ]; do
    # once frames are being written, rank 1 of this job is killed
    if [ "$(ls "$DIR/cut" 2>/dev/null | grep -c 'pfm$')" -ge 1 ]; then
        for p in /proc/[0-9]*; do
            env=$( (tr '\0' '\n' <"$p/environ") 2>/dev/null)
            if echo "$env" | grep -qx "VCT_TEST_MARK=$mark" &&
                echo "$env" | grep -qx "OMPI_COMM_WORLD_RANK=1"; then
                victim=${p#/proc/}
            fi
        done
    fi
    [ -z "$victim" ] && sleep 0.1
    tries=$((tries + 1))
done
[ -n "$victim" ] && kill -9 "$victim"
wait $job
status=$?
written=$(ls "$DIR/cut" | grep -c 'pfm$')
if [ -z "$victim" ]; then
    fail "kill: rank 1 was not found running"
elif [ $status -ne 0 ] && grep -q "rank 1" "$DIR/cut.log" && [ "$written" -lt 16 ]; then
    ok "a killed rank ends the job (exit $status) naming it; $written of 16 frames written"
else
    cat "$DIR/cut.log"
    fail "kill: exit $status, $written frames written"
fi
whole=0
for f in "$DIR"/cut/*; do
    case $f in
    *.pfm) cmp -s "$f" "$DIR/whole/$(basename "$f")" && whole=$((whole + 1)) ;;
    *) fail "kill: $(basename "$f") is left in the output folder" ;;
    esac
done
if [ $whole -eq "$written" ]; then
    ok "every file the killed job left is whole"
else
    fail "kill: $whole of $written files equal the uninterrupted run's"
fi
# shellcheck disable=SC2086
mpi -np 3 "$VCT" render "$ANIMATED" $kill_args --resume -o "$DIR/cut/f_%02d.pfm" \
    >"$DIR/log" 2>&1 || { cat "$DIR/log"; fail "--resume did not finish"; }
same=0
for f in 00 01 02 03 04 05 06 07 08 09 10 11 12 13 14 15; do
    cmp -s "$DIR/cut/f_$f.pfm" "$DIR/whole/f_$f.pfm" && same=$((same + 1))
done
if [ $same -eq 16 ] && grep -q "rendering $((16 - written))" "$DIR/log"; then
    ok "--resume rendered the $((16 - written)) frames left: the files equal an uninterrupted run's"
else
    cat "$DIR/log"
    fail "--resume: $same of 16 files equal the uninterrupted run's"
fi

# What is not split is refused on every rank, with a message.
for refused in "--method pt --time 1 --size 16 16" "--method vct --aov --size 16 16" \
    "--method pm --size 16 1"; do
    # shellcheck disable=SC2086
    if mpi -np 2 "$VCT" render "$BOX" $refused -o "$DIR/no.pfm" \
        >"$DIR/log" 2>&1; then
        fail "$refused under mpirun was not refused"
    elif grep -q "vct render:" "$DIR/log" && [ ! -e "$DIR/no.pfm" ]; then
        ok "$refused under mpirun is refused: $(grep 'vct render:' "$DIR/log" | head -1)"
    else
        cat "$DIR/log"
        fail "$refused: no message, or a file"
    fi
done

echo "test_mpi: $failures failed"
[ $failures -eq 0 ]
