#!/bin/bash
# The one command for hikari's benchmarks beside the peers' (../bench/SPEC.md, B1-B5):
#   bench/run.sh                 RUNS=3 interleaved process runs per configuration
#   RUNS=1 bench/run.sh          quick
#   ONLY="B1" bench/run.sh       B1 and B2 only (B3: POV-Ray scene; B4: rasterization beside Mesa's
#                                llvmpipe; B5: path-traced Cornell box beside Blender's Cycles when
#                                `blender` is installed)
# Builds hikari (Release), generates bumpy1m into build/bench/data, runs `hikari bench` and,
# when the peers are there, the peers' programs interleaved with ours, then prints medians and
# ratios (bench/aggregate.py). B1p16 is B1 as 4x4 packets (`hikari bench B1 --packets`), compared
# with Embree's rtcIntersect16 line. The peers' C++ programs are taken from $PEERS/build or built
# out of tree into build/bench/peers (make -C $PEERS BIN=...; needs libembree-dev for B1/B2,
# libosmesa6-dev for B4); without them, or without $PEERS at all, only hikari's lines are written.
# B4 runs llvmpipe (osmesa_bench) twice per configuration: glibc's default malloc and the SPEC's
# tuned malloc (large mmap/trim thresholds), the weaker and the stronger peer figure.
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
PEERS=${PEERS:-/work/shared/bench/peers}
BUILD=${BUILD:-$ROOT/build}
RUNS=${RUNS:-3}
ONLY=${ONLY:-"B1 B3 B4 B5"}
OUT=$BUILD/bench
LOG=${LOG:-$OUT/logs/$(date +%Y%m%d-%H%M%S)}
has() { [[ " $ONLY " == *" $1 "* ]]; }

cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null || exit 1
cmake --build "$BUILD" --target hikari_cli > /dev/null || exit 1
HIKARI=$BUILD/hikari
mkdir -p "$OUT/data" "$OUT/out" "$LOG"
BUNNY=$ROOT/scenes/models/stanford-bunny.obj
BUMPY=$OUT/data/bumpy1m.obj
# bumpy1m's generator lives with the peers; without them (and no earlier copy) only the bunny runs.
MESHES="bunny bumpy1m"
if [ ! -s "$BUMPY" ]; then
  if [ -f "$PEERS/gen_bumpy.py" ]; then
    python3 "$PEERS/gen_bumpy.py" "$BUMPY" >&2 || exit 1
  else
    echo "run.sh: no $PEERS/gen_bumpy.py: bumpy1m left out" >&2
    MESHES="bunny"
  fi
fi
# A peer program: the peers' own build, else ours out of tree in $OUT/peers, (re)built here when the
# Debian packages it needs are installed (a failed build, logged, just leaves that peer out).
# Without $PEERS there are no peers, even if an earlier build is still in $OUT/peers.
peer() {
  [ -f "$PEERS/Makefile" ] || return 0
  if [ -x "$PEERS/build/$1" ]; then echo "$PEERS/build/$1"; return; fi
  make -s -C "$PEERS" BIN="$OUT/peers" "$OUT/peers/$1" >> "$LOG/peers_build.log" 2>&1
  if [ -x "$OUT/peers/$1" ]; then echo "$OUT/peers/$1"; fi
}
EMBREE=""; has B1 && EMBREE=$(peer embree_bench)
OSMESA=""; has B4 && OSMESA=$(peer osmesa_bench)
POVRAY=""; [ -f "$PEERS/whitted.pov" ] && POVRAY=$(command -v povray || true)
BLENDER=""; [ -f "$PEERS/cornell_cycles.py" ] && BLENDER=$(command -v blender || true)
TUNED_MALLOC="MALLOC_MMAP_THRESHOLD_=268435456 MALLOC_TRIM_THRESHOLD_=1073741824"
# B4's coverage check: osmesa_bench saves its image but prints no count, so `hikari compare`
# counts the pixels that differ from an image of the clear colour (51,64,76) alone.
CLEAR_PNG=$OUT/out/b4_clear.png
if [ -n "$OSMESA" ] && [ ! -s "$CLEAR_PNG" ]; then
  python3 - "$CLEAR_PNG" << 'EOF'
import struct, sys, zlib
w, h = 1920, 1080
row = b"\0" + bytes([51, 64, 76, 255]) * w  # filter byte 0, then RGBA pixels
def chunk(kind, data): return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
                              + chunk(b"IDAT", zlib.compress(row * h, 9)) + chunk(b"IEND", b""))
EOF
fi
{ date -Is; grep -m1 "model name" /proc/cpuinfo; nproc; uname -r; git -C "$ROOT" rev-parse --short HEAD; } > "$LOG/machine.txt"

# B3's wall clock is read from bash's own $EPOCHREALTIME (bash 5, microseconds): no process is
# started to read it, so nothing but hikari's own run falls between the two readings.
for r in $(seq "$RUNS"); do
  echo "== run $r/$RUNS" >&2
  if has B1; then
    for mesh in $MESHES; do for t in 1 2; do
      file=$BUNNY; [ $mesh = bumpy1m ] && file=$BUMPY
      # B1p16: B1 as 4x4 packets, against Embree's rtcIntersect16 (its B1p16 line).
      for b in B1 B1p16 B2; do
        args=$b; [ $b = B1p16 ] && args="B1 --packets"
        "$HIKARI" bench $args --mesh "$file" --threads $t | sed "s/\"mesh\": \"[^\"]*\"/\"mesh\": \"$mesh\"/" >> "$LOG/hikari.jsonl"
      done
      [ -n "$EMBREE" ] && "$EMBREE" "$file" $t 5 2>> "$LOG/embree.err" | sed "s/mesh=[^ ]*/mesh=$mesh/" >> "$LOG/embree.log"
    done; done
  fi
  if has B3; then
    for t in 1 2; do
      t0=$EPOCHREALTIME
      "$HIKARI" render "$ROOT/scenes/bench/whitted.json" --threads $t -q -o "$OUT/out/whitted_hikari.png"
      t1=$EPOCHREALTIME
      echo "{\"bench\": \"B3\", \"threads\": $t, \"wall_ms\": $(( (${t1/./} - ${t0/./} + 500) / 1000 ))}" >> "$LOG/hikari.jsonl"
      if [ -n "$POVRAY" ]; then
        (cd "$OUT" && /usr/bin/time -f "WALL_S %e" "$POVRAY" "$PEERS/whitted.pov" +W1920 +H1080 -A +WT$t -D +FN \
          +Oout/whitted_pov.png > /dev/null 2> "$LOG/pov.tmp")
        tr '\r' '\n' < "$LOG/pov.tmp" | grep -E "Trace Time|WALL_S" > "$LOG/pov_t${t}_r$r.log"
        rm -f "$LOG/pov.tmp"
      fi
    done
  fi
  # B4: hikari's rasterizer (one process per variant), then llvmpipe (one process draws both
  # variants, 3 warm-up + 20 timed frames each) with glibc's default and with the tuned malloc.
  if has B4; then
    for mesh in $MESHES; do for t in 1 2; do
      file=$BUNNY; [ $mesh = bumpy1m ] && file=$BUMPY
      for v in plain shadow; do
        "$HIKARI" bench B4 --mesh "$file" --threads $t $([ $v = shadow ] && echo --shadow) \
          | sed "s/\"mesh\": *\"[^\"]*\"/\"mesh\": \"$mesh\"/" >> "$LOG/hikari.jsonl"
      done
      if [ -n "$OSMESA" ]; then
        # Images (for the coverage count) once per mesh, from the first run's 2-thread process.
        png=""; [ $r = 1 ] && [ $t = 2 ] && png=$OUT/out/b4_llvmpipe
        [ -n "$png" ] && rm -f "${png}_$(basename "$file" .obj)"_*.png   # never count an earlier run's image
        LP_NUM_THREADS=$t "$OSMESA" "$file" 20 3 $png 2>> "$LOG/osmesa.err" \
          | sed "s/mesh=[^ ]*/mesh=$mesh/" >> "$LOG/osmesa.log"
        env $TUNED_MALLOC LP_NUM_THREADS=$t "$OSMESA" "$file" 20 3 2>> "$LOG/osmesa.err" \
          | sed "s/mesh=[^ ]*/mesh=$mesh/" >> "$LOG/osmesa.log"
        for v in plain shadow; do   # osmesa_bench names its images PREFIX_<file stem>_<variant>.png
          img=${png}_$(basename "$file" .obj)_$v.png
          if [ -n "$png" ] && [ -s "$img" ]; then
            covered=$("$HIKARI" compare "$CLEAR_PNG" "$img" | sed -n 's/^differing pixels \([0-9]*\) .*/\1/p')
            echo "COVERED mesh=$mesh variant=$v covered=$covered" >> "$LOG/osmesa.log"
          fi
        done
      fi
    done; done
  fi
  # B5: hikari's path tracer and Cycles, each one warm-up and 3 timed renders in one process
  # (the Cycles script renders with 2 threads, as the SPEC fixes).
  if has B5; then
    "$HIKARI" bench B5 --threads 2 >> "$LOG/hikari.jsonl"
    if [ -n "$BLENDER" ]; then
      "$BLENDER" -b --factory-startup -noaudio -P "$PEERS/cornell_cycles.py" -- 3 "$OUT/out/cornell_cycles.png" 2>&1 \
        | grep "^RESULT" >> "$LOG/cycles.log"
    fi
  fi
done
if has B3 && [ -s "$OUT/out/whitted_pov.png" ]; then
  echo "B3 PSNR hikari vs POV-Ray (dB): $("$HIKARI" compare --psnr "$OUT/out/whitted_hikari.png" "$OUT/out/whitted_pov.png")" > "$LOG/psnr.txt"
fi
python3 "$ROOT/bench/aggregate.py" "$LOG" | tee "$LOG/table.md"
