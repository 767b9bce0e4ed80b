#!/usr/bin/env bash
# Makes every picture in docs/screenshots/ from the current build, on a virtual screen with settings of its
# own (two throttles open on the demo's running trains) and the embedded simulated station. Needs xvfb-run
# (package xvfb) and a build in build/.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
shots=docs/screenshots
config=$(mktemp -d)
trap 'rm -rf "$config"' EXIT
mkdir -p "$config/Stellwerk"
printf '[throttles]\nlocomotives=0x4001, 0x4002\n' >"$config/Stellwerk/Stellwerk.conf"

app() { XDG_CONFIG_HOME=$config xvfb-run -a -s "-screen 0 1600x1000x24" build/app/gui/stellwerk "$@"; }

app --screenshot "$shots/main-window.png"
LANG=de_DE.UTF-8 app --screenshot "$shots/main-window-de.png"
app --decode docs/examples/bus-session.log --panel frameDecoderPanel --screenshot "$shots/frame-decoder.png"
app --panel statusPanel --screenshot "$shots/status-gauges.png"
app --panel busMonitorPanel --screenshot "$shots/bus-monitor.png"

# The single panels, drawn offscreen by their widget tests.
export QT_QPA_PLATFORM=offscreen STELLWERK_SCREENSHOT_DIR=$PWD/$shots
build/tests/ui/stellwerk-ui-tests --gtest_filter='*Screenshot*:ThrottlePanelTest.ThreeThrottles*:TrackPlanPanelTest.TheDemoPlanIsDrawnInLightAndDarkPalettes'
