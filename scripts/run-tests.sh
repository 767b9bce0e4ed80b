#!/usr/bin/env bash
# Sets up and builds Stellwerk with warnings as errors (scripts/setup.sh --werror), then runs every test
# with ctest: the tests that mostly wait (20 s outages) beside the others (scripts/common.sh). The last
# lines printed are the waiting tests' summary; the exit code is 1 when a test of either run failed.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh --werror

# shellcheck source=common.sh
source scripts/common.sh
seed_test_costs build

# Widget tests draw into memory; they need no screen.
export QT_QPA_PLATFORM=offscreen

printf '==> Running the tests\n'
# Each test picks its own free ports, so they run one per core, and the waiting ones beside them.
run_split_ctest --test-dir build --output-on-failure
