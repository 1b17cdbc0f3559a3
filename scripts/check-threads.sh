#!/usr/bin/env bash
# Builds the test program under ThreadSanitizer (clang, -O1, line tables only) in build-tsan and
# runs the tests of everything that renders in parallel. Any data race fails. A third build, so
# CI leaves it out; run it before a release and after touching a parallel loop.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DHIKARI_SANITIZE=thread
cmake --build build-tsan --target hikari_tests
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tests/tsan.supp" \
    build-tsan/tests/hikari_tests \
    --gtest_filter='*Thread*:*Parallel*:Scanline*:DepthSort*:ZBuffer*:Whitted*:Bvh*'
