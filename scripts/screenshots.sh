#!/usr/bin/env bash
# Makes every picture in docs/screenshots/ from the current build, on a virtual screen with settings of its
# own (two throttles open on the demo's running trains) and the embedded simulated station. Needs xvfb-run
# (package xvfb), openbox and a build in build/.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
shots=docs/screenshots
config=$(mktemp -d)
trap 'rm -rf "$config"' EXIT
mkdir -p "$config/Stellwerk"
printf '[throttles]\nlocomotives=0x4001, 0x4002\n' >"$config/Stellwerk/Stellwerk.conf"

app() { XDG_CONFIG_HOME=$config xvfb-run -a -s "-screen 0 1920x1080x24" build/app/gui/stellwerk "$@"; }

# The first start on a laptop (1366 × 768) under a window manager (openbox), with fresh settings: the window
# as it really opens there, no throttle open yet, the throttle page offers locomotives to drive.
first_start() { # LANG file
    local first
    first=$(mktemp -d)
    cat >"$first/run.sh" <<INSIDE
#!/usr/bin/env bash
QT_QPA_PLATFORM=xcb "$PWD/build/app/gui/stellwerk" --simulated --screenshot "$PWD/$shots/$2"
openbox --exit 2>/dev/null
INSIDE
    chmod +x "$first/run.sh"
    XDG_CONFIG_HOME=$first LANG=$1 xvfb-run -a -s "-screen 0 1366x768x24" \
        openbox --sm-disable --startup "$first/run.sh" 2>/dev/null || true
    rm -rf "$first"
}
first_start en_US.UTF-8 main-window-first-start.png
first_start de_DE.UTF-8 main-window-first-start-de.png

# The whole desk on a laptop's screen and on a full-HD one, in English and German.
app --size 1366x768 --screenshot "$shots/main-window.png"
LANG=de_DE.UTF-8 app --size 1366x768 --screenshot "$shots/main-window-de.png"
app --size 1920x1080 --screenshot "$shots/main-window-1920x1080.png"
LANG=de_DE.UTF-8 app --size 1920x1080 --screenshot "$shots/main-window-de-1920x1080.png"
app --decode docs/examples/bus-session.log --panel frameDecoderPanel --screenshot "$shots/frame-decoder.png"
app --panel statusPanel --screenshot "$shots/status-gauges.png"
app --panel busMonitorPanel --screenshot "$shots/bus-monitor.png"
# The Devices panel with the demo's RO module and OpenRailCAN devices, at both sizes and in both languages.
app --panel devicesPanel --size 1366x768 --screenshot "$shots/devices.png"
LANG=de_DE.UTF-8 app --panel devicesPanel --size 1366x768 --screenshot "$shots/devices-de.png"
app --panel devicesPanel --size 1920x1080 --screenshot "$shots/devices-1920x1080.png"
LANG=de_DE.UTF-8 app --panel devicesPanel --size 1920x1080 --screenshot "$shots/devices-de-1920x1080.png"
# The Handhelds panel with the demo's MS1, at both sizes and in both languages.
app --panel locomotivePanel --size 1366x768 --screenshot "$shots/locomotives-z21.png"
LANG=de_DE.UTF-8 app --panel locomotivePanel --size 1366x768 --screenshot "$shots/locomotives-z21-de.png"
app --panel handheldsPanel --size 1366x768 --screenshot "$shots/handhelds.png"
LANG=de_DE.UTF-8 app --panel handheldsPanel --size 1366x768 --screenshot "$shots/handhelds-de.png"
app --panel handheldsPanel --size 1920x1080 --screenshot "$shots/handhelds-1920x1080.png"
LANG=de_DE.UTF-8 app --panel handheldsPanel --size 1920x1080 --screenshot "$shots/handhelds-de-1920x1080.png"

# The Automatic panel after a restart: the demo's three trains placed again from the book where they stood,
# waiting for Resume (nothing moves by itself), one with a schedule; at both sizes and in both languages.
book=$config/data/Stellwerk/Stellwerk/trains
mkdir -p "$book"
cat >"$book/station-simulated.json" <<'BOOK'
{"trains":[
 {"loc":16385,"length":220,"pushPull":false,"block":"Gleis 1","blockId":0,"towards":"b","automatic":true,
  "schedule":{"loop":true,"next":0,"stops":[{"block":"Gleis 2","dwell":20},{"block":"Gleis 1","dwell":30}]}},
 {"loc":16386,"length":400,"pushPull":true,"block":"Block 2","blockId":0,"towards":"b","automatic":true,
  "schedule":{"loop":false,"next":0,"stops":[]}},
 {"loc":24,"length":180,"pushPull":false,"block":"Gleis 2","blockId":0,"towards":"b","automatic":false,
  "schedule":{"loop":false,"next":0,"stops":[]}}]}
BOOK
auto_app() { XDG_DATA_HOME=$config/data app --panel automaticPanel "$@"; }
auto_app --size 1366x768 --screenshot "$shots/automatic.png"
LANG=de_DE.UTF-8 auto_app --size 1366x768 --screenshot "$shots/automatic-de.png"
auto_app --size 1920x1080 --screenshot "$shots/automatic-1920x1080.png"
LANG=de_DE.UTF-8 auto_app --size 1920x1080 --screenshot "$shots/automatic-de-1920x1080.png"

# The single panels, drawn offscreen by their widget tests (among them the plan with its blocks and the popup of
# a block, track-plan-blocks.png and -de.png); and the whole desk with the track power off and with the station
# silent ("not reported"), at both sizes and in both languages (StationTrustTest).
export QT_QPA_PLATFORM=offscreen STELLWERK_SCREENSHOT_DIR=$PWD/$shots
build/tests/ui/stellwerk-ui-tests --gtest_filter='*Screenshot*:TrackPlanBlocksTest.Screenshots*:ThrottlePanelTest.ThreeThrottles*:TrackPlanPanelTest.TheDemoPlanIsDrawnInLightAndDarkPalettes:StationTrustTest.While*:StationTrustTest.WithThePowerOff*:AfterTroubleOnTheDesk.AStalledStation*:TrackPlanAutomationTest.ThreeRunningTrains*:AutomaticPanelTest.German*:ThrottlesPanelTest.Screenshot*:PhonesDialogTest.FitsASmallScreen*'
