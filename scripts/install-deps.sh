#!/usr/bin/env bash
# Installs the Debian 12 packages hikari builds with; does nothing when they are all present.
#   --tests  also what the browser and spreadsheet tests need: chromium, node and npm,
#            playwright-core (npm ci in tests/browser, from its lock file), LibreOffice Calc
#   --ci     also CI's tools (clang, clang-format, clang-tidy, the sanitizer runtimes); implies --tests
set -euo pipefail
cd "$(dirname "$0")/.."
tests=false
ci=false
for option in "$@"; do
    case "$option" in
        --tests) tests=true ;;
        --ci) ci=true tests=true ;;
        *) echo "install-deps.sh: unknown option $option (use --tests or --ci)" >&2; exit 2 ;;
    esac
done

packages=(
    cmake ninja-build g++ pkg-config
    nlohmann-json3-dev libtinyobjloader-dev libcli11-dev libfmt-dev libtbb-dev
    libstb-dev libtinyexr-dev libtinygltf-dev zlib1g-dev libgtest-dev libxlsxwriter-dev
    libcpp-httplib-dev
    # MPI: frames and one image shared among ranks (docs/distributed.md; HIKARI_MPI), and its tests.
    libopenmpi-dev openmpi-bin
    # The Python module (python/) and its tests.
    pybind11-dev python3-dev python3-numpy python3-pytest
)
# The browser test drives hikari serve's page in Debian's chromium; LibreOffice recalculates the
# --formulas workbook in tests/python/test_xlsx_formulas.py; ffmpeg encodes `-o turntable.mp4`
# (docs/animation.md), and its test needs it too.
if $tests; then
    packages+=(chromium libreoffice-calc-nogui ffmpeg)
    # A node with its npm from elsewhere (NodeSource, nvm) will do; Debian's otherwise.
    command -v npm > /dev/null || packages+=(nodejs npm)
fi
# CI also checks formatting and builds with sanitizers (clang-tidy: scripts/check-tidy.sh, by hand).
if $ci; then
    packages+=(clang clang-format clang-tidy libclang-rt-14-dev git)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    echo "Installing: ${missing[*]}" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# playwright-core for the browser test, exactly as the lock file says (once).
if $tests && [ ! -d tests/browser/node_modules/playwright-core ]; then
    npm ci --prefix tests/browser --no-audit --no-fund --loglevel=error
fi
