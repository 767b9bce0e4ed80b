#!/usr/bin/env bash
# Builds Stellwerk with AddressSanitizer and UndefinedBehaviorSanitizer into build-sanitize/ (through
# scripts/setup.sh --preset sanitize, which installs missing packages first) and runs the tests there.
# Any sanitizer finding, a leak included, fails the test it happens in.
#
#   scripts/sanitize.sh [core | REGEX]
#
# Without an argument every test runs. `core` builds and runs only the tests of tests/core and tests/e2e
# (what CI runs: the parsers and sessions under the sanitizers; the command-line programs' own tests run
# in the main build and their parsers in the fuzz targets); any other argument is a ctest -R regex over the
# test names. The sanitizer
# options are the environment of the "sanitize" test preset in CMakePresets.json. The last lines printed
# are ctest's summary, and the exit code is ctest's.
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
    build=(--target stellwerk-tests-core --target stellwerk-tests-e2e)
    selection=(--label-regex '^(core|e2e)$')
    ;;
*) selection=(--tests-regex "$1") ;;
esac

bash scripts/setup.sh --preset sanitize "${build[@]}"

printf '==> Running the tests under AddressSanitizer and UndefinedBehaviorSanitizer\n'
exec ctest --preset sanitize -j"$(nproc)" "${selection[@]}"
