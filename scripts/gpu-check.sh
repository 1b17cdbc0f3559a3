#!/usr/bin/env bash
# The GPU check of issue 46, for a machine with an NVIDIA GPU (docs/gpu.md); about 8 minutes on
# 16 cores. It
#   1. builds hikari with CUDA (HIKARI_CUDA=ON) and lists the devices it finds;
#   2. runs the GPU tests (the kernels as a CUDA grid against their CPU run; none may be skipped);
#   3. renders every scene of scenes/ with --method raytrace on the CPU and with --device cuda,
#      and compares them (PSNR >= 60 dB; scenes the kernels do not take yet are listed); the same
#      with --method zbuffer, whose id buffers must be identical and colours >= 60 dB; then with
#      --method path (64 spp, caustics from the camera paths, as the GPU's wavefront kernels take
#      them): the same Sobol' samples on both, so the images' means agree far within their noise
#      (relative difference <= 1 %);
#   4. prints the timings of B3 (the Whitted scene, 1920x1080), B5 (the Cornell box, 512x512,
#      64 spp, 8 bounces) and B4 (the shadow-mapped bunny, 1920x1080, zbuffer; --stats phases),
#      CPU beside GPU, and B1 once its kernels exist.
# Exit status 0 when every check that can run passes. Usage: scripts/gpu-check.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-gpu}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
started=$(date +%s)
echo "== hikari GPU check, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD)"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true

echo "== 1. build (CUDA on)"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHIKARI_CUDA=ON -DHIKARI_PYTHON=OFF \
    -DHIKARI_MPI=OFF >"$out/cmake.log" || { cat "$out/cmake.log"; exit 1; }
grep 'hikari: CUDA' "$out/cmake.log" || true
cmake --build "$build" --target hikari_cli hikari_tests -j "$(nproc)" >"$out/build.log" 2>&1 ||
    { tail -40 "$out/build.log"; exit 1; }
hikari="$build/hikari"
"$hikari" info --devices
echo "build: $(( $(date +%s) - started )) s"

echo "== 2. GPU tests"
gtest="$build/tests/hikari_tests"
if "$gtest" --gtest_filter='WhittedKernels.*:ZBufferKernels.*:PathKernels.*:DeviceCli.*' >"$out/tests.log" 2>&1; then
    grep -E '^\[  (PASSED|SKIPPED) ' "$out/tests.log" || true
else
    grep -E '^\[  FAILED|Failure|error' "$out/tests.log" | head -20
    fail "GPU tests"
fi
# Skipped GPU tests mean no device was found: the check has not checked anything.
if grep -q '^\[  SKIPPED \] \(WhittedKernels\|ZBufferKernels\|PathKernels\).CudaGridMatchesTheCpuRun' "$out/tests.log"; then
    fail "the CUDA test was skipped: no usable device"
fi

echo "== 3. CPU and GPU renders of scenes/*.json (raytrace, 640 px wide)"
for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    if ! "$hikari" render "$scene" -m raytrace --width 640 -o "$out/$name-cpu.png" \
        >"$out/$name-cpu.log" 2>&1; then
        echo "  $name: the CPU render failed: $(tail -1 "$out/$name-cpu.log")"
        continue
    fi
    if ! "$hikari" render "$scene" -m raytrace --width 640 --device cuda \
        -o "$out/$name-gpu.png" >"$out/$name-gpu.log" 2>&1; then
        if grep -q 'not in the kernels yet\|past the kernels' "$out/$name-gpu.log"; then
            echo "  $name: not on the GPU yet ($(sed 's/^hikari: error: //' "$out/$name-gpu.log"))"
        else
            fail "$name: $(tail -1 "$out/$name-gpu.log")"
        fi
        continue
    fi
    psnr=$("$hikari" compare "$out/$name-cpu.png" "$out/$name-gpu.png" --psnr)
    verdict=ok
    # inf (identical) or at least 60 dB.
    awk -v p="$psnr" 'BEGIN { exit !(p == "inf" || p + 0 >= 60) }' || verdict=FAIL
    echo "  $name: PSNR $psnr dB $verdict"
    [ "$verdict" = ok ] || fail "$name: PSNR $psnr dB < 60"
done
echo "== 3b. CPU and GPU renders of scenes/*.json (zbuffer, 640 px wide): ids identical"
for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    args=("$scene" -m zbuffer --width 640)
    if ! "$hikari" render "${args[@]}" -o "$out/$name-zcpu.png" >"$out/$name-zcpu.log" 2>&1 ||
        ! "$hikari" render "${args[@]}" --aov id -o "$out/$name-zcpu.pfm" >/dev/null 2>&1; then
        echo "  $name: the CPU render failed: $(tail -1 "$out/$name-zcpu.log")"
        continue
    fi
    if ! "$hikari" render "${args[@]}" --device cuda -o "$out/$name-zgpu.png" \
        >"$out/$name-zgpu.log" 2>&1; then
        if grep -q 'not in the kernels yet' "$out/$name-zgpu.log"; then
            echo "  $name: not on the GPU yet ($(sed 's/^hikari: error: //' "$out/$name-zgpu.log"))"
        else
            fail "$name (zbuffer): $(tail -1 "$out/$name-zgpu.log")"
        fi
        continue
    fi
    "$hikari" render "${args[@]}" --device cuda --aov id -o "$out/$name-zgpu.pfm" >/dev/null 2>&1 ||
        fail "$name (zbuffer): the GPU id render failed"
    ids=$("$hikari" compare "$out/$name-zcpu.pfm" "$out/$name-zgpu.pfm" |
        sed -n 's/^differing pixels \([0-9]*\) .*/\1/p')
    psnr=$("$hikari" compare "$out/$name-zcpu.png" "$out/$name-zgpu.png" --psnr)
    verdict=ok
    [ "$ids" = 0 ] && awk -v p="$psnr" 'BEGIN { exit !(p == "inf" || p + 0 >= 60) }' || verdict=FAIL
    echo "  $name: ids differing at ${ids:-?} pixels, PSNR $psnr dB $verdict"
    [ "$verdict" = ok ] || fail "$name (zbuffer): ids differ at ${ids:-?} pixels or PSNR $psnr dB < 60"
done
pfm_mean() {  # the mean of a PFM image's RGB values (python3's standard library alone)
    python3 -c '
import struct, sys
data = open(sys.argv[1], "rb").read()
lines = data.split(b"\n", 3)
w, h = map(int, lines[1].split()); scale = float(lines[2])
values = struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * w * h), lines[3][: 12 * w * h])
print(sum(values) / len(values))' "$1"
}
echo "   path (256 px wide, 64 spp, --caustics path): CPU path tracer beside the GPU's kernels"
for scene in scenes/*.json scenes/bench/cornell.json; do
    name=$(basename "$scene" .json)
    args=(-m path --width 256 --spp 64 --caustics path)
    if ! "$hikari" render "$scene" "${args[@]}" -o "$out/$name-path-cpu.pfm" \
        >"$out/$name-path-cpu.log" 2>&1; then
        echo "  $name: the CPU render failed: $(tail -1 "$out/$name-path-cpu.log")"
        continue
    fi
    if ! "$hikari" render "$scene" "${args[@]}" --device cuda -o "$out/$name-path-gpu.pfm" \
        >"$out/$name-path-gpu.log" 2>&1; then
        if grep -q 'not in the kernels yet' "$out/$name-path-gpu.log"; then
            echo "  $name: path not on the GPU yet ($(sed 's/^hikari: error: //' "$out/$name-path-gpu.log"))"
        else
            fail "$name (path): $(tail -1 "$out/$name-path-gpu.log")"
        fi
        continue
    fi
    cpu=$(pfm_mean "$out/$name-path-cpu.pfm")
    gpu=$(pfm_mean "$out/$name-path-gpu.pfm")
    verdict=ok
    awk -v a="$cpu" -v b="$gpu" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 0.01 * a + 1e-6) }' ||
        verdict=FAIL
    echo "  $name (path): mean $cpu on the CPU, $gpu on the GPU $verdict"
    [ "$verdict" = ok ] || fail "$name (path): means $cpu and $gpu differ by more than 1 %"
done

echo "== 4. timings (render time as --stats reports it: BVH build, upload and kernels)"
render_ms() {  # prints the render time of `hikari render ARGS --stats`
    "$hikari" render "$@" --stats -o "$out/timing.png" 2>&1 |
        sed -n 's/.*render \([0-9.]*\) ms.*/\1/p' | head -1
}
for device in cpu cuda; do
    # Twice: the first GPU render also creates the CUDA context.
    render_ms scenes/bench/whitted.json -m raytrace --device "$device" >/dev/null || true
    ms=$(render_ms scenes/bench/whitted.json -m raytrace --device "$device" || true)
    echo "  B3 (Whitted, 1920x1080) on $device: ${ms:-refused} ms (target on the GPU: <= 0.5 ms)"
done
for device in cpu cuda; do
    render_ms scenes/bench/cornell.json -m path --width 64 --height 64 --spp 4 --device "$device" \
        >/dev/null || true
    ms=$(render_ms scenes/bench/cornell.json -m path --width 512 --height 512 --spp 64 \
        --max-depth 8 --caustics path --device "$device" || true)
    echo "  B5 (Cornell box, 512x512, 64 spp, 8 bounces) on $device: ${ms:-refused} ms (target on the GPU: <= 50 ms)"
done
echo "  B1 (1M-triangle mesh, primary rays): not on the GPU yet (target >= 2 Grays/s)"
for device in cpu cuda; do
    # B4-like: the shadow-mapped bunny at 1920x1080 (its shadow pass included: one render draws
    # its maps; a session keeps them for the frames after), every --stats phase.
    "$hikari" render scenes/bunny.json -m zbuffer --width 1920 --height 1080 --device "$device" \
        -o "$out/timing.png" >/dev/null 2>&1 || true
    echo "  B4 (bunny frame, 1920x1080, shadow-mapped zbuffer) on $device (target on the GPU: <= 1 ms a frame):"
    "$hikari" render scenes/bunny.json -m zbuffer --width 1920 --height 1080 --device "$device" \
        --stats -o "$out/timing.png" 2>&1 | sed -n 's/^hikari: stats (zbuffer): /    /p' || true
done

echo "== done in $(( $(date +%s) - started )) s, $failures failure(s)"
[ "$failures" -eq 0 ]
