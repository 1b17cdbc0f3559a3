#!/bin/bash
# The one command for hikari's benchmarks beside the peers' (../bench/SPEC.md, B1-B3, B5):
#   bench/run.sh                 RUNS=3 interleaved process runs per configuration
#   RUNS=1 bench/run.sh          quick
#   ONLY="B1" bench/run.sh       B1 and B2 only (B3: POV-Ray scene; B5: path-traced Cornell box
#                                beside Blender's Cycles when `blender` is installed)
# Builds hikari (Release), generates bumpy1m into build/bench/data, runs `hikari bench` and,
# when the peers are built and installed (make -C $PEERS; Embree, POV-Ray), the peers'
# programs interleaved with ours, then prints medians and ratios (bench/aggregate.py). B1p16 is
# B1 as 4x4 packets (`hikari bench B1 --packets`), compared with Embree's rtcIntersect16 line.
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
PEERS=${PEERS:-/work/shared/bench/peers}
BUILD=${BUILD:-$ROOT/build}
RUNS=${RUNS:-3}
ONLY=${ONLY:-"B1 B3 B5"}
OUT=$BUILD/bench
LOG=${LOG:-$OUT/logs/$(date +%Y%m%d-%H%M%S)}
has() { [[ " $ONLY " == *" $1 "* ]]; }

cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null || exit 1
cmake --build "$BUILD" --target hikari_cli > /dev/null || exit 1
HIKARI=$BUILD/hikari
mkdir -p "$OUT/data" "$OUT/out" "$LOG"
BUNNY=$ROOT/scenes/models/stanford-bunny.obj
BUMPY=$OUT/data/bumpy1m.obj
[ -s "$BUMPY" ] || python3 "$PEERS/gen_bumpy.py" "$BUMPY" >&2 || exit 1
EMBREE=$PEERS/build/embree_bench
[ -x "$EMBREE" ] || EMBREE=""
POVRAY=$(command -v povray || true)
BLENDER=$(command -v blender || true)
{ date -Is; grep -m1 "model name" /proc/cpuinfo; nproc; uname -r; git -C "$ROOT" rev-parse --short HEAD; } > "$LOG/machine.txt"

# B3's wall clock is read from bash's own $EPOCHREALTIME (bash 5, microseconds): no process is
# started to read it, so nothing but hikari's own run falls between the two readings.
for r in $(seq "$RUNS"); do
  echo "== run $r/$RUNS" >&2
  if has B1; then
    for mesh in bunny bumpy1m; do for t in 1 2; do
      file=$BUNNY; [ $mesh = bumpy1m ] && file=$BUMPY
      # B1p16: B1 as 4x4 packets, against Embree's rtcIntersect16 (its B1p16 line).
      for b in B1 B1p16 B2; do
        args=$b; [ $b = B1p16 ] && args="B1 --packets"
        "$HIKARI" bench $args --mesh "$file" --threads $t | sed "s/\"mesh\": \"[^\"]*\"/\"mesh\": \"$mesh\"/" >> "$LOG/hikari.jsonl"
      done
      [ -n "$EMBREE" ] && "$EMBREE" "$file" $t 5 | sed "s/mesh=[^ ]*/mesh=$mesh/" >> "$LOG/embree.log" 2>> "$LOG/embree.err"
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
