#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for SECONDS (default 60)
# on its seed corpus in fuzz/corpus/. Crashes are written to fuzz/crashes/<target>/; copy each
# into tests/data/fuzz-regressions/<target>/ once fixed so the test suite keeps replaying it.
# Usage: scripts/fuzz.sh [--build DIR] [SECONDS] [TARGET...]
#   --build DIR  use DIR, already configured with -DHIKARI_FUZZ=ON and clang (CI's sanitizer
#                build), instead of configuring build-fuzz.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-fuzz
if [ "${1:-}" = "--build" ]; then
    build=$2
    shift 2
else
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DHIKARI_FUZZ=ON -DHIKARI_BUILD_TESTS=OFF >/dev/null
fi
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene_json obj mtl ply gltf image scene_texture jpeg gltf_image)

cmake --build "$build" --target "${targets[@]/#/fuzz_}"

status=0
for t in "${targets[@]}"; do
    work=$build/corpus/$t
    mkdir -p "$work" "fuzz/crashes/$t"
    echo "== fuzz_$t for ${seconds}s"
    # A fixed seed: the same build explores the same inputs first, so a finding reproduces.
    if ! LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0" "$build/fuzz/fuzz_$t" "$work" "fuzz/corpus/$t" \
        -seed=1 -max_total_time="$seconds" -artifact_prefix="fuzz/crashes/$t/" -max_len=65536 -timeout=10 \
        -rss_limit_mb=4096 -print_final_stats=1 2>"$build/fuzz_$t.log"; then
        echo "fuzz_$t FOUND A PROBLEM: see $build/fuzz_$t.log and fuzz/crashes/$t/"
        tail -n 40 "$build/fuzz_$t.log"
        status=1
    else
        grep -E "stat::number_of_executed_runs|cov:" "$build/fuzz_$t.log" | tail -n 2
    fi
done
exit $status
