#!/usr/bin/env bash
# Builds Stellwerk's libFuzzer targets (fuzz/) with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# into build-fuzz/ and runs each for SECONDS (default 60) from its seed corpus, one after the other.
# Installs clang and its fuzzer runtime with apt-get when they are missing.
#
#   scripts/fuzz.sh [SECONDS]        FUZZ_TARGETS="frame_text cs2_document" scripts/fuzz.sh 600
#
# Prints executions and exec/s per target; exits non-zero when any target finds a crash, a leak, a
# sanitizer report or a broken invariant (the input is kept as build-fuzz/findings/<target>-crash-*).
# New inputs that reach new code are kept in build-fuzz/corpus/<target> for the next run.
set -euo pipefail

seconds="${1:-60}"
[[ $seconds =~ ^[0-9]+$ ]] || {
    printf 'usage: scripts/fuzz.sh [SECONDS]\n' >&2
    exit 2
}

# shellcheck source=common.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/common.sh"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
readonly build=build-fuzz shared="${STELLWERK_SHARED_DIR:-../shared}"


apt_install() {
    command -v apt-get >/dev/null || fail "apt-get not found: install clang and its libFuzzer runtime by hand"
    say "Installing $*"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "$@"
}

# True when clang can link a libFuzzer program (the runtime is a separate package on Debian and Ubuntu).
can_link_fuzzer() {
    local probe
    probe=$(mktemp -d)
    printf '%s\n' '#include <cstddef>' '#include <cstdint>' \
        'extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }' >"$probe/probe.cpp"
    clang++ -fsanitize=fuzzer,address,undefined "$probe/probe.cpp" -o "$probe/probe" 2>/dev/null
    local status=$?
    rm -rf "$probe"
    return $status
}

install_clang() {
    command -v clang++ >/dev/null || apt_install clang
    if ! can_link_fuzzer; then
        local major
        major=$(clang++ -dumpversion | cut -d. -f1)
        apt_install "libclang-rt-$major-dev"
        can_link_fuzzer || fail "clang++ cannot link libFuzzer programs even with libclang-rt-$major-dev"
    fi
}

build_targets() {
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    say "Configuring the fuzz targets with clang into $build/"
    CC=clang CXX=clang++ cmake -S fuzz -B "$build" "${launcher[@]}" >/dev/null
    say "Building with $(nproc) parallel jobs"
    cmake --build "$build" -j"$(nproc)"
}

# Seeds from the real station files in ../shared/corpus, prefixed with each target's choice byte
# (they stay outside the project: they are read in place and copied into build-fuzz/ only).
shared_seeds() {
    local target=$1 folder="$build/shared-seeds/$1" file n=0
    rm -rf "$folder" && mkdir -p "$folder"
    [[ -d $shared/corpus ]] || return 0
    while IFS= read -r -d '' file; do
        n=$((n + 1))
        case "$target" in
        cs2_document) { printf '\x00' && cat "$file"; } >"$folder/$n" ;;
        track_graph) cp "$file" "$folder/$n" ;;
        config_stream)
            { printf '\x80' && cat "$file"; } >"$folder/$n-compressed"
            { printf '\x81' && cat "$file"; } >"$folder/$n-text"
            ;;
        esac
    done < <(find "$shared/corpus" -name '*.cs2' -print0)
    if [[ $target == loco_picture ]]; then
        cp resources/demo-layout/icons/*.png "$folder/"
    fi
    if [[ $target == frame_text ]]; then
        while IFS= read -r -d '' file; do
            split -l 1 -a 3 "$file" "$folder/$(basename "$file")-"
        done < <(find "$shared/corpus" -name '*.txt' -print0)
    fi
}

# Runs one target; prints "<target> <executions> <exec/s> <status>".
run_target() {
    local target=$1 corpus="$build/corpus/$1" log="$build/logs/$1.log"
    mkdir -p "$corpus" "$build/findings" "$build/logs"
    shared_seeds "$target"
    local status=0
    # Inputs up to 4 KiB (longer seeds, the real files, are cut): under the sanitizers a .cs2 reader
    # takes about 3 us per byte, so whole 64 KiB files would make a few executions per second.
    "$build/fuzz-$target" -max_total_time="$seconds" -max_len=4096 -timeout=25 -rss_limit_mb=2048 \
        -print_final_stats=1 \
        -artifact_prefix="$build/findings/$target-" "$corpus" "fuzz/seeds/$target" "$build/shared-seeds/$target" \
        >"$log" 2>&1 || status=$?
    local runs rate
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n1)
    printf '%s %s %s %s\n' "$target" "${runs:-0}" "${rate:-0}" "$status"
}

install_clang
build_targets

mapfile -t targets < <(sed -n '/^set(STELLWERK_FUZZ_TARGETS/,/^)/{s/^ \{4\}\([a-z_0-9]*\).*/\1/p}' fuzz/targets.cmake)
if [[ -n ${FUZZ_TARGETS:-} ]]; then
    read -r -a targets <<<"$FUZZ_TARGETS"
fi

# One target per core at a time (each fuzzes on one core); the results are read back in the targets' order.
jobs=$(nproc)
say "Running ${#targets[@]} targets for $seconds s each, $jobs at a time"
running=()
for target in "${targets[@]}"; do
    [[ -x $build/fuzz-$target ]] || fail "no fuzz target '$target' in $build/"
    mkdir -p "$build/logs"
    run_target "$target" >"$build/logs/$target.result" &
    running+=($!)
    if [[ ${#running[@]} -ge $jobs ]]; then
        wait "${running[0]}" || true
        running=("${running[@]:1}")
    fi
done
wait || true

failed=0
results=()
for target in "${targets[@]}"; do
    result=$(cat "$build/logs/$target.result")
    results+=("$result")
    read -r _ runs rate status <<<"$result"
    say "$target: $runs executions, $rate exec/s"
    if [[ $status -ne 0 ]]; then
        failed=1
        printf '%s: FINDING (exit %s), see %s/logs/%s.log and %s/findings/\n' "$target" "$status" "$build" \
            "$target" "$build" >&2
        grep -m3 -E 'ERROR: |FUZZ INVARIANT|runtime error' "$build/logs/$target.log" >&2 || true
    fi
done

printf '\n%-16s %14s %10s  %s\n' target executions exec/s result
for result in "${results[@]}"; do
    read -r target runs rate status <<<"$result"
    printf '%-16s %14s %10s  %s\n' "$target" "$runs" "$rate" "$([[ $status -eq 0 ]] && echo ok || echo FINDING)"
done
exit "$failed"
