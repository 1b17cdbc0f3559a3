#!/bin/sh
# Frames shared among 3 MPI ranks on loopback (docs/distributed.md) are the files one process
# writes, bit for bit, for a turntable and for a scene's animation block; a rerun under MPI
# skips them all. One image shared by tiles among the ranks (path tracing with caustics, Whitted,
# AOVs, depth cueing, a method rank 0 renders alone) is the file one process writes, bit for
# bit. Exit 77 (skipped) when mpirun is not installed.
# Usage: mpi_frames_test.sh HIKARI SOURCE_DIR
set -eu
hikari=$1
source_dir=$2
if ! command -v mpirun > /dev/null; then
    echo "SKIPPED: mpirun is not installed (apt-get install openmpi-bin libopenmpi-dev)"
    exit 77
fi
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mpi="mpirun -np 3 --oversubscribe --allow-run-as-root"
# Open MPI on loopback only: no network interfaces probed.
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
compare() {  # compare DIR_A DIR_B COUNT
    test "$(ls "$1" | wc -l)" -eq "$3" || { echo "FAIL: $1 holds $(ls "$1" | wc -l) files, not $3"; exit 1; }
    for f in "$1"/*; do
        cmp "$f" "$2/$(basename "$f")" || { echo "FAIL: $f differs"; exit 1; }
    done
}
mkdir "$dir/one" "$dir/ranks"
"$hikari" render --width 40 -m zbuffer,raytrace -q --turntable 7 -o "$dir/one/t_%02d.png"
$mpi "$hikari" render --width 40 -m zbuffer,raytrace -q --turntable 7 -o "$dir/ranks/t_%02d.png"
compare "$dir/ranks" "$dir/one" 14

scene="$source_dir/scenes/animation.json"
common="-m path --spp 1 --width 32 --height 24 --threads 1 -q --frames 3-6"
"$hikari" render "$scene" $common -o "$dir/one/a_%02d.exr"
$mpi "$hikari" render "$scene" $common -o "$dir/ranks/a_%02d.exr"
compare "$dir/ranks" "$dir/one" 18

out=$($mpi "$hikari" render "$scene" -m path --spp 1 --width 32 --height 24 --threads 1 --frames 3-6 \
    -o "$dir/ranks/a_%02d.exr" 2>&1)
echo "$out" | grep -q "wrote 0 frames.*4 already there" || { echo "FAIL: the rerun rendered again: $out"; exit 1; }

# One image, its tiles shared among the ranks and gathered on rank 0. Odd sizes leave part tiles.
mkdir "$dir/still_one" "$dir/still_ranks"
still() {  # still NAME ARGS...: one process and 3 ranks write the same file
    name=$1
    shift
    "$hikari" render "$@" -q -o "$dir/still_one/$name"
    $mpi "$hikari" render "$@" -q -o "$dir/still_ranks/$name"
}
still glass.exr "$source_dir/scenes/cornell-glass.json" -m path --spp 3 --width 53 --height 37
still whitted.png "$source_dir/scenes/whitted.json" --width 61 --height 45 --spp 2
still depth.pfm "$source_dir/scenes/assignment.json" --width 45 --height 33 --aov depth
still cued.png "$source_dir/scenes/assignment.json" -m path --spp 2 --width 45 --height 33 \
    --depth-cue 2,12
still zbuffer.png "$source_dir/scenes/assignment.json" -m zbuffer --width 45 --height 33
compare "$dir/still_ranks" "$dir/still_one" 5

# What would give the ranks' tiles different samples is refused before anything is written.
if $mpi "$hikari" render -m path --time-limit 1 --width 16 -q -o "$dir/still_ranks/t.png" 2> "$dir/err"; then
    echo "FAIL: --time-limit under mpirun was not refused"
    exit 1
fi
grep -q "give --spp instead" "$dir/err" || { echo "FAIL: no clear error: $(cat "$dir/err")"; exit 1; }
test ! -e "$dir/still_ranks/t.png" || { echo "FAIL: a refused render wrote its file"; exit 1; }
echo "PASS"
