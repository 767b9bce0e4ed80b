#!/usr/bin/env bash
# The first start on a fresh settings folder under a real window manager (openbox on Xvfb), at a laptop's
# 1366x768 and at 1920x1080, in English and German: the window with its frame fits the screen's free area,
# the status bar (station lamp, track power) is on the screen, the plan is zoomed large enough for its
# names, and no panel scrolls sideways. Offscreen tests cannot see this: there is no frame and no window
# manager there.
#
#   first-start-under-window-manager.sh STELLWERK_BINARY MINIMUM_TILE
#
# Exits 77 (skipped) when xvfb-run or openbox is missing; scripts/setup.sh installs both.
set -euo pipefail

stellwerk=$(realpath "$1")
minimum_tile=$2

for tool in xvfb-run openbox; do
    if ! command -v "$tool" >/dev/null; then
        echo "SKIPPED: $tool is not installed (scripts/setup.sh installs it)"
        exit 77
    fi
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Inside the virtual screen: openbox first, Stellwerk once openbox runs (--startup; on the X server even
# when the tests run offscreen), then openbox ends.
cat >"$scratch/stellwerk.sh" <<INSIDE
#!/usr/bin/env bash
QT_QPA_PLATFORM=xcb "$stellwerk" --simulated --report-geometry >"\$REPORT" 2>"\$REPORT.err"
openbox --exit 2>/dev/null
INSIDE
chmod +x "$scratch/stellwerk.sh"

# "frame 0,0 1366x768" → "0 0 1366 768"
numbers() { grep "^$1 " "$2" | sed -E 's/^[a-z ]+ //; s/[,x]/ /g'; }

inside() { # x y w h inside ax ay aw ah
    (($1 >= $5 && $2 >= $6 && $1 + $3 <= $5 + $7 && $2 + $4 <= $6 + $8))
}

failures=0
check() { # size language
    local size=$1 language=$2 report="$scratch/report-$1-$2"
    mkdir -p "$scratch/config-$size-$language"
    REPORT="$report" XDG_CONFIG_HOME="$scratch/config-$size-$language" LANG="$language" LC_ALL='' LANGUAGE='' \
        timeout 60 xvfb-run -a -s "-screen 0 ${size}x24" \
        openbox --sm-disable --startup "$scratch/stellwerk.sh" 2>"$scratch/openbox.err" || true
    if ! grep -q '^frame ' "$report" 2>/dev/null; then
        echo "FAIL $size $language: Stellwerk reported nothing"
        cat "$report.err" 2>/dev/null || true
        failures=$((failures + 1))
        return
    fi
    echo "$size $language:"
    sed 's/^/    /' "$report"
    local available frame window bar tile
    read -r -a available < <(numbers available "$report")
    read -r -a frame < <(numbers frame "$report")
    read -r -a window < <(numbers window "$report")
    read -r -a bar < <(numbers "status bar" "$report")
    tile=$(grep '^plan tile ' "$report" | sed 's/plan tile //')
    if ((frame[3] <= window[3])); then
        echo "FAIL $size $language: the window has no title bar: no window manager framed it"
        failures=$((failures + 1))
    fi
    if ! inside "${frame[@]}" "${available[@]}"; then
        echo "FAIL $size $language: the window with its frame does not fit the screen's free area"
        failures=$((failures + 1))
    fi
    if ! inside "${bar[@]}" "${available[@]}" || ((bar[2] < available[2] * 9 / 10)); then
        echo "FAIL $size $language: the status bar is not (wholly) on the screen"
        failures=$((failures + 1))
    fi
    if (($(grep '^scrolling sideways ' "$report" | sed 's/scrolling sideways //') > 0)); then
        echo "FAIL $size $language: a panel scrolls sideways: its dock was arranged for another size"
        failures=$((failures + 1))
    fi
    if ((tile < minimum_tile)); then
        echo "FAIL $size $language: the plan's tiles are $tile px, too small for their names ($minimum_tile px)"
        failures=$((failures + 1))
    fi
}

for size in 1366x768 1920x1080; do
    for language in en_US.UTF-8 de_DE.UTF-8; do
        check "$size" "$language"
    done
done
if ((failures > 0)); then
    echo "$failures problem(s) at the first start"
    exit 1
fi
echo "The first window fits the screen with its frame and status bar at both sizes in both languages."
