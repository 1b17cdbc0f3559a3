#!/usr/bin/env bash
# Runs clang-tidy (.clang-tidy) over the library and the program, using the compile commands of
# the build directory given (default: build). Any finding fails.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
git ls-files 'src/*.cpp' 'apps/*.cpp' | xargs -P "$(nproc)" -n 4 clang-tidy -p "$build" --quiet
echo "clang-tidy: clean"
