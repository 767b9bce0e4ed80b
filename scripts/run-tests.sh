#!/usr/bin/env bash
# Sets up and builds Stellwerk with warnings as errors (scripts/setup.sh --werror), then runs every test
# with ctest. The last lines printed are ctest's summary, and the exit code is ctest's.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh --werror

# shellcheck source=common.sh
source scripts/common.sh
seed_test_costs build

# Widget tests draw into memory; they need no screen.
export QT_QPA_PLATFORM=offscreen

printf '==> Running the tests\n'
# Each test picks its own free ports, so they run one per core.
exec ctest --test-dir build --output-on-failure -j"$(nproc)"
