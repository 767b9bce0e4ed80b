#!/usr/bin/env bash
# Builds Stellwerk with AddressSanitizer and UndefinedBehaviorSanitizer into build-sanitize/ (through
# scripts/setup.sh --preset sanitize, which installs missing packages first) and runs the tests there.
# Any sanitizer finding, a leak included, fails the test it happens in.
#
#   scripts/sanitize.sh [core | REGEX]
#
# Without an argument every test runs. `core` builds and runs the tests of the sessions, transports, model
# and simulator (tests/core, label "sessions") and tests/e2e: what CI runs. The pure codecs and file
# formats (label "codec") are left to the main build and to the fuzz targets, which run their parsers under
# these same sanitizers; the command-line programs' tests to the main build. Any other argument is a ctest
# -R regex over the test names. The sanitizer options are the environment of the "sanitize" test preset
# in CMakePresets.json. The last lines printed are ctest's summary, and the exit code is ctest's.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

build=()
selection=()
case "${1:-}" in
'') ;;
-h | --help)
    sed -n '2,13s/^# \{0,1\}//p' "$0"
    exit 0
    ;;
core)
    build=(--target stellwerk-tests-sessions --target stellwerk-tests-e2e)
    selection=(--label-regex '^(sessions|e2e)$')
    ;;
*) selection=(--tests-regex "$1") ;;
esac

bash scripts/setup.sh --preset sanitize "${build[@]}"

# shellcheck source=common.sh
source scripts/common.sh
seed_test_costs build-sanitize

printf '==> Running the tests under AddressSanitizer and UndefinedBehaviorSanitizer\n'
if [[ ${selection[0]:-} == --tests-regex ]]; then
    exec ctest --preset sanitize -j"$(nproc)" "${selection[@]}"
fi
run_split_ctest --preset sanitize "${selection[@]}"
