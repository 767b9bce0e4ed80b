# Shared by the setup scripts (sourced, not run): messages, failing with the script's name, running a
# command as root (directly when we are root, else through sudo), and installing missing packages.

say() { printf '==> %s\n' "$*"; }
fail() {
    printf '%s: %s\n' "${0##*/}" "$*" >&2
    exit 1
}

as_root() {
    if [[ $(id -u) -eq 0 ]]; then
        "$@"
    elif command -v sudo >/dev/null; then
        sudo "$@"
    else
        fail "need root rights to install packages, but this is not root and sudo is missing"
    fi
}

# Prints those of the given packages that dpkg does not show as fully installed (removed ones keep a status
# entry too).
missing_packages() {
    local package status
    for package in "$@"; do
        status=$(dpkg -s "$package" 2>/dev/null || true)
        [[ $status == *"Status: install ok installed"* ]] || printf '%s\n' "$package"
    done
}

# Installs those of the given packages that are missing, with apt-get.
install_packages() {
    command -v apt-get >/dev/null || fail "apt-get not found: this script supports Debian and Ubuntu only"
    local missing
    mapfile -t missing < <(missing_packages "$@")
    if [[ ${#missing[@]} -eq 0 ]]; then
        say "All $# packages are installed already"
        return
    fi
    say "Installing ${#missing[@]} missing packages: ${missing[*]}"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Gives ctest the durations of the long tests (the outages of 20 s, the stalled stations) before its first
# run in a build folder, so that it starts them first and the short ones fill the other core meanwhile;
# without them a fresh build runs them last, one after the other. ctest keeps its own figures afterwards.
seed_test_costs() {
    local costs="$1/Testing/Temporary/CTestCostData.txt"
    [[ -f $costs ]] && return
    mkdir -p "$1/Testing/Temporary"
    cp "$(dirname "${BASH_SOURCE[0]}")/../tests/long-tests.txt" "$costs"
}

# The tests that mostly wait (an outage or a stalled station of 20 s: 10 s and more in
# tests/long-tests.txt), as one ctest regular expression.
waiting_tests_regex() {
    local names
    names=$(awk '$3 >= 10 {print $1}' "$(dirname "${BASH_SOURCE[0]}")/../tests/long-tests.txt" |
        sed 's/\./\\./g' | paste -sd '|')
    printf '^(%s)$' "$names"
}

# Runs ctest with the given arguments (a --test-dir or --preset and a selection) as two runs at once: the
# waiting tests two at a time, beside the others on every core. A single `ctest -j` would hold a core for
# each waiting test and leave it idle for its 20 s. The waiting tests' report follows the others'; fails
# when either run fails.
run_split_ctest() {
    local regex log waiting status=0 waiting_status=0
    regex=$(waiting_tests_regex)
    # Listing the tests first lets each test program list its tests once (gtest discovery at test time):
    # two ctest runs discovering at once would both write the list, and each test would run twice.
    ctest "$@" --show-only >/dev/null
    log=$(mktemp)
    ctest "$@" -j2 --tests-regex "$regex" >"$log" 2>&1 &
    waiting=$!
    ctest "$@" -j"$(nproc)" --exclude-regex "$regex" || status=$?
    wait "$waiting" || waiting_status=$?
    say "The waiting tests (outages, stalled stations), run beside the others"
    cat "$log"
    rm -f "$log"
    [[ $status -eq 0 && $waiting_status -eq 0 ]]
}
