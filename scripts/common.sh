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
