#!/usr/bin/env bash
# Sets up and builds Stellwerk (scripts/setup.sh), then starts the desktop application.
# Every argument is passed on to the application, e.g. `scripts/run-app.sh --help`.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh

if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" && -z "${QT_QPA_PLATFORM:-}" ]]; then
    cat >&2 <<'MESSAGE'

Stellwerk is built, but there is no screen to show it on: neither DISPLAY nor WAYLAND_DISPLAY is set.
Start it from a desktop session (or ssh -X), or run it on a virtual screen:

    xvfb-run -a build/app/gui/stellwerk --screenshot stellwerk.png   # saves a picture and exits
MESSAGE
    exit 1
fi

printf '==> Starting build/app/gui/stellwerk %s\n' "$*"
exec build/app/gui/stellwerk "$@"
