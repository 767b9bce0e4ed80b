#!/usr/bin/env bash
# Prepares a Debian 12 (bookworm) or Ubuntu 24.04 machine for Stellwerk and builds it into build/:
# installs the packages with apt-get when some are missing, then configures and builds with CMake.
#
#   scripts/setup.sh [--werror | --no-werror] [--preset NAME] [--target NAME]...
#
# --werror (or STELLWERK_WERROR=ON) builds Stellwerk's own code with warnings as errors, as CI does;
# --no-werror (or STELLWERK_WERROR=OFF) switches that off again. Without either, the choice of the last
# configure run in build/ is kept, so switching between run-tests.sh and run-app.sh does not rebuild.
# --preset NAME configures and builds a preset of CMakePresets.json instead, into that preset's folder
# (e.g. --preset sanitize: build-sanitize/, with AddressSanitizer and UndefinedBehaviorSanitizer).
# --target NAME builds only that target (repeatable), e.g. stellwerk-tests-core for the tests of tests/core.
set -euo pipefail

readonly packages=(
    build-essential cmake pkg-config
    qt6-base-dev qt6-serialbus-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libqt6svg6 qt6-translations-l10n
    libgl1-mesa-dev zlib1g-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    xvfb xauth openbox
)

# shellcheck source=common.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/common.sh"

werror="${STELLWERK_WERROR:-}"
preset=""
targets=()
while [[ $# -gt 0 ]]; do
    case "$1" in
    --werror) werror=ON ;;
    --no-werror) werror=OFF ;;
    --preset)
        [[ $# -ge 2 ]] || fail "--preset needs a name (see CMakePresets.json)"
        preset=$2
        shift
        ;;
    --target)
        [[ $# -ge 2 ]] || fail "--target needs a target name"
        targets+=(--target "$2")
        shift
        ;;
    -h | --help)
        sed -n '2,12s/^# \{0,1\}//p' "$0"
        exit 0
        ;;
    *) fail "unknown option '$1' (try --help)" ;;
    esac
    shift
done

cd "$(dirname "${BASH_SOURCE[0]}")/.."


configure() {
    local options=(-S . -B build) where=build/
    if [[ -n "$preset" ]]; then
        options=(--preset "$preset")
        where="the folder of preset '$preset'"
    fi
    if [[ -n "$werror" ]]; then
        options+=("-DSTELLWERK_WERROR=$werror")
    fi
    say "Configuring with CMake into $where${werror:+ (warnings as errors: $werror)}"
    cmake "${options[@]}"
}

build() {
    say "Building with $(nproc) parallel jobs"
    if [[ -n "$preset" ]]; then
        cmake --build --preset "$preset" -j"$(nproc)" "${targets[@]}"
    else
        cmake --build build -j"$(nproc)" "${targets[@]}"
    fi
}

install_packages "${packages[@]}"
configure
build
if [[ -n "$preset" ]]; then
    say "Build finished (preset $preset)"
else
    say "Build finished: build/app/gui/stellwerk"
fi
