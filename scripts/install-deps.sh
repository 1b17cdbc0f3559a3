#!/usr/bin/env bash
# Installs the Debian 12 packages hikari builds with; does nothing when they are all present.
set -euo pipefail

packages=(
    cmake ninja-build g++ pkg-config
    nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libfmt-dev libtbb-dev
    libstb-dev libtinyexr-dev libtinygltf-dev zlib1g-dev libgtest-dev libxlsxwriter-dev
    # The Python module (python/) and its tests.
    pybind11-dev python3-dev python3-numpy python3-pytest
)
# CI also checks formatting, runs clang-tidy and builds with sanitizers.
if [ "${1:-}" = "--ci" ]; then
    packages+=(clang clang-format clang-tidy libclang-rt-14-dev git)
    # LibreOffice recalculates the --formulas workbook in tests/python/test_xlsx_formulas.py.
    packages+=(libreoffice-calc-nogui)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "Installing: ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
